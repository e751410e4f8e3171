#include "Net/Private/TickColumns.h"

#include <functional>
#include <stdexcept>

namespace proxima
{

void appendTick(const HapticState& state, net::TickColumns& columns)
{
  columns.add_tick(state.tick);
  columns.add_t(state.time);
  const auto add = [](google::protobuf::RepeatedField<double>* column, const Vec3& v) {
    column->Add(v.x);
    column->Add(v.y);
    column->Add(v.z);
  };
  add(columns.mutable_finger(), state.finger);
  add(columns.mutable_proxy(), state.proxy);
  add(columns.mutable_force(), state.force);
  columns.add_contacts(state.numContacts);
  columns.add_iterations(state.iterations);
  columns.add_solve_ns(state.solveNanoseconds);
  columns.add_object(state.contactObject);
  columns.add_flags(state.conditions.bits());
}

void forEachTick(const net::TickColumns& columns, const std::function<void(const HapticState&)>& f)
{
  const int n = columns.tick_size();
  if (columns.t_size() != n || columns.finger_size() != 3 * n || columns.proxy_size() != 3 * n ||
      columns.force_size() != 3 * n || columns.contacts_size() != n ||
      columns.iterations_size() != n || columns.solve_ns_size() != n ||
      columns.object_size() != n || columns.flags_size() != n)
  {
    throw std::runtime_error("the server sent ticks whose columns differ in length");
  }
  for (int i = 0; i < n; ++i)
  {
    HapticState state;
    state.tick = columns.tick(i);
    state.time = columns.t(i);
    state.finger =
      Vec3{columns.finger(3 * i), columns.finger(3 * i + 1), columns.finger(3 * i + 2)};
    state.proxy = Vec3{columns.proxy(3 * i), columns.proxy(3 * i + 1), columns.proxy(3 * i + 2)};
    state.force = Vec3{columns.force(3 * i), columns.force(3 * i + 1), columns.force(3 * i + 2)};
    state.numContacts = columns.contacts(i);
    state.iterations = columns.iterations(i);
    state.solveNanoseconds = columns.solve_ns(i);
    state.contactObject = columns.object(i);
    state.conditions = TickConditions(columns.flags(i));
    f(state);
  }
}

void appendBodyPose(const BodyPoseRow& row, net::BodyPoseColumns& columns)
{
  columns.add_tick(row.tick);
  columns.add_t(row.time);
  columns.add_object(row.object);
  for (int i = 0; i < 3; ++i)
  {
    columns.add_position(row.position[i]);
  }
  for (const double component : row.orientation)
  {
    columns.add_orientation(component);
  }
  columns.add_q(row.jointPosition);
}

void forEachBodyPose(const net::BodyPoseColumns& columns,
                     const std::function<void(const BodyPoseRow&)>& f)
{
  const int n = columns.tick_size();
  if (columns.t_size() != n || columns.object_size() != n || columns.position_size() != 3 * n ||
      columns.orientation_size() != 4 * n || columns.q_size() != n)
  {
    throw std::runtime_error("the server sent body poses whose columns differ in length");
  }
  for (int i = 0; i < n; ++i)
  {
    BodyPoseRow row;
    row.tick = columns.tick(i);
    row.time = columns.t(i);
    row.object = columns.object(i);
    row.position =
      Vec3{columns.position(3 * i), columns.position(3 * i + 1), columns.position(3 * i + 2)};
    for (int k = 0; k < 4; ++k)
    {
      row.orientation[k] = columns.orientation(4 * i + k);
    }
    row.jointPosition = columns.q(i);
    f(row);
  }
}

} // namespace proxima
