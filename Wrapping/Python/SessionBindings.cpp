// proxima._proxima.Session: a HapticSession (Runtime/HapticSession.h) on the scene of the
// keywords, stepped tick by tick from Python or run over a whole path.
#include "Bindings.h"

#include "IO/Scene/SceneBuilder.h"
#include "IO/ScriptedRun/ScriptedRun.h"
#include "Runtime/HapticSession.h"

#include <memory>

namespace proxima::python
{
py::array_t<double> vectorArray(const Vec3& v)
{
  py::array_t<double> array(3);
  double* out = array.mutable_data();
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
  return array;
}

namespace
{
Vec3 point(const py::object& value)
{
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || array.size() != 3)
  {
    throw py::value_error("expected a point of 3 numbers x, y, z");
  }
  const double* in = array.data();
  return Vec3{in[0], in[1], in[2]};
}

py::dict stateDict(const HapticState& state)
{
  py::dict tick;
  tick["tick"] = state.tick;
  tick["t"] = state.time;
  tick["finger"] = vectorArray(state.finger);
  tick["proxy"] = vectorArray(state.proxy);
  tick["force"] = vectorArray(state.force);
  tick["contacts"] = state.numContacts;
  tick["iterations"] = state.iterations;
  tick["solve_ns"] = state.solveNanoseconds;
  tick["object"] = state.contactObject;
  tick["flags"] = state.conditions.bits();
  return tick;
}

// The session with the scene it was built on.
class PythonSession
{
public:
  explicit PythonSession(const py::kwargs& keywords)
  {
    const ScriptedRunSettings settings = settingsFromKeywords(keywords);
    LoadedScene loaded = loadScene(settings);
    checkRadiusAgainstScene(settings, loaded);
    std::shared_ptr<TickDynamics> bodies = sceneDynamics(settings, loaded);
    HapticSessionSettings session;
    session.proxy = proxyParameters(settings);
    tickBudget(settings, TickWorkBudget{}).applyTo(session.proxy);
    session.servo = servoParameters(settings);
    session.rate = settings.rate;
    m_session = std::make_unique<HapticSession>(
      std::shared_ptr<const CollisionScene>(std::move(loaded.scene)), session);
    m_session->setDynamics(std::move(bodies));
  }

  // Where each body's object is now: a list of {object, translation, rotation (3 x 3)}, a point
  // p of the object as placed being at rotation @ p + translation.
  py::list bodies() const
  {
    py::list list;
    const TickDynamics* dynamics = m_session->dynamics();
    if (dynamics == nullptr)
    {
      return list;
    }
    BodyPoses poses;
    dynamics->poses(poses);
    for (int b = 0; b < poses.count; ++b)
    {
      const RigidTransform& pose = poses.poses[b];
      py::array_t<double> rotation({3, 3});
      double* out = rotation.mutable_data();
      for (int r = 0; r < 3; ++r)
      {
        out[3 * r] = pose.row[r].x;
        out[3 * r + 1] = pose.row[r].y;
        out[3 * r + 2] = pose.row[r].z;
      }
      py::dict body;
      body["object"] = poses.objects[b];
      body["translation"] = vectorArray(pose.translation);
      body["rotation"] = rotation;
      list.append(body);
    }
    return list;
  }

  py::dict step(const py::object& finger) { return stateDict(m_session->step(point(finger))); }

  py::dict run(const py::object& path)
  {
    ScriptedRunSettings named;
    const FingerPath fingerPath = fingerPathFrom(path, named);
    std::vector<HapticState> ticks;
    {
      py::gil_scoped_release released;
      ticks = m_session->run(fingerPath);
    }
    return traceColumns(ticks);
  }

  py::array_t<double> place(const py::object& finger)
  {
    return vectorArray(m_session->placeProxy(point(finger)).position);
  }

  py::array_t<double> proxy() const { return vectorArray(m_session->proxy()); }

private:
  std::unique_ptr<HapticSession> m_session;
};
} // namespace

void addSessionBindings(py::module_& module)
{
  py::class_<PythonSession>(module, "Session",
                            "A scene, its proxy solver and the servo's force stage, stepped by "
                            "hand: keywords as proxima.run's, without the path.")
    .def(py::init<const py::kwargs&>())
    .def("step", &PythonSession::step, py::arg("finger"),
         "One tick with the finger at (x, y, z): a dict of the tick (proxy, force, contacts...). "
         "The first tick places the proxy.")
    .def("run", &PythonSession::run, py::arg("path"),
         "A whole path (file or (N, 4) array) in lockstep from its first sample: trace columns.")
    .def("place", &PythonSession::place, py::arg("finger"),
         "Places the proxy for a finger there (outside a closed object that holds it) and "
         "restarts the clock; returns where it went.")
    .def_property_readonly("proxy", &PythonSession::proxy, "The proxy's centre (metres).")
    .def_property_readonly("bodies", &PythonSession::bodies,
                           "Where the scene's bodies are now (paper section 6): a list of "
                           "{object, translation, rotation}, empty for a scene without bodies.");
}

} // namespace proxima::python
