// Keywords to ScriptedRunSettings, finger paths from Python, and traces to numpy columns.
#include "Bindings.h"

#include "IO/InputChecks/InputError.h"
#include "IO/PathAndTrace/FingerPathFile.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <sstream>

namespace proxima::python
{
namespace
{
using Setter = std::function<void(ScriptedRunSettings&, const py::handle&)>;

Setter number(double ScriptedRunSettings::*field)
{
  return [field](ScriptedRunSettings& settings, const py::handle& value) {
    settings.*field = value.cast<double>();
  };
}

Setter text(std::string ScriptedRunSettings::*field)
{
  return [field](ScriptedRunSettings& settings, const py::handle& value) {
    // A path-like object (pathlib.Path) is taken as its string.
    settings.*field = py::str(value).cast<std::string>();
  };
}

// The keywords, as `proxima run` spells its options with '_' for '-'.
const std::map<std::string, Setter>& setters()
{
  static const std::map<std::string, Setter> table = {
    {"mesh", text(&ScriptedRunSettings::mesh)},
    {"scene", text(&ScriptedRunSettings::scene)},
    {"scale", number(&ScriptedRunSettings::scale)},
    {"radius", number(&ScriptedRunSettings::radius)},
    {"stiffness", number(&ScriptedRunSettings::stiffness)},
    {"rate", number(&ScriptedRunSettings::rate)},
    {"max_force", number(&ScriptedRunSettings::maxForce)},
    {"max_iterations", [](ScriptedRunSettings& settings,
                          const py::handle& value) { settings.maxIterations = value.cast<int>(); }},
    {"skin", number(&ScriptedRunSettings::skin)},
    {"shading", text(&ScriptedRunSettings::shading)},
    {"feature_angle", number(&ScriptedRunSettings::featureAngle)},
    {"static_friction", number(&ScriptedRunSettings::staticFriction)},
    {"dynamic_friction", number(&ScriptedRunSettings::dynamicFriction)},
    {"viscosity", number(&ScriptedRunSettings::viscosity)},
    {"texture", text(&ScriptedRunSettings::texture)},
    {"texture_role", text(&ScriptedRunSettings::textureRole)},
    {"texture_amplitude", number(&ScriptedRunSettings::textureAmplitude)},
    {"texture_channel", text(&ScriptedRunSettings::textureChannel)},
    {"tick_budget", text(&ScriptedRunSettings::tickBudget)},
  };
  return table;
}
} // namespace

ScriptedRunSettings settingsFromKeywords(const py::kwargs& keywords)
{
  ScriptedRunSettings settings;
  for (const auto& [key, value] : keywords)
  {
    const std::string name = py::str(key).cast<std::string>();
    if (value.is_none())
    {
      continue; // None: the option's default, as when it is not given
    }
    const auto setter = setters().find(name);
    if (setter == setters().end())
    {
      throw py::type_error("unexpected keyword '" + name +
                           "' (the keywords are proxima run's options, with _ for -)");
    }
    setter->second(settings, value);
  }
  checkScriptedRunSettings(settings);
  return settings;
}

FingerPath fingerPathFrom(const py::object& path, ScriptedRunSettings& settings)
{
  if (py::isinstance<py::str>(path) || py::hasattr(path, "__fspath__"))
  {
    settings.path = py::str(path).cast<std::string>();
    return readFingerPathFile(settings.path);
  }
  settings.path = "path array";
  const auto rows = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(path);
  if (!rows || rows.ndim() != 2 || rows.shape(1) != 4)
  {
    throw InputError(settings.path, "expected a file name or an (N, 4) array of rows t, x, y, z");
  }
  if (rows.shape(0) == 0)
  {
    throw InputError(settings.path, "no rows");
  }
  const auto view = rows.unchecked<2>();
  FingerPath fingerPath;
  for (py::ssize_t row = 0; row < view.shape(0); ++row)
  {
    for (py::ssize_t column = 0; column < 4; ++column)
    {
      if (!std::isfinite(view(row, column)))
      {
        throw InputError(settings.path,
                         "row " + std::to_string(row) + ": " + "txyz"[column] + " is not finite");
      }
    }
    if (!fingerPath.empty() && view(row, 0) < fingerPath.endTime())
    {
      std::ostringstream message;
      message.precision(17);
      message << "row " << row << ": time goes backwards (" << view(row, 0) << " after "
              << fingerPath.endTime() << ")";
      throw InputError(settings.path, message.str());
    }
    fingerPath.append(view(row, 0), Vec3{view(row, 1), view(row, 2), view(row, 3)});
  }
  return fingerPath;
}

py::array_t<double> fingerPathArray(const FingerPath& path)
{
  py::array_t<double> rows({static_cast<py::ssize_t>(path.size()), py::ssize_t{4}});
  auto view = rows.mutable_unchecked<2>();
  for (std::size_t i = 0; i < path.size(); ++i)
  {
    const auto row = static_cast<py::ssize_t>(i);
    view(row, 0) = path.times[i];
    view(row, 1) = path.positions[i].x;
    view(row, 2) = path.positions[i].y;
    view(row, 3) = path.positions[i].z;
  }
  return rows;
}

namespace
{
// One column of the trace, filled by `value` for each tick.
template <typename T, typename Value>
py::array_t<T> column(const std::vector<HapticState>& ticks, Value value)
{
  py::array_t<T> array(static_cast<py::ssize_t>(ticks.size()));
  T* out = array.mutable_data();
  for (const HapticState& tick : ticks)
  {
    *out++ = static_cast<T>(value(tick));
  }
  return array;
}
} // namespace

py::dict traceColumns(const std::vector<HapticState>& ticks)
{
  // The columns of TraceWriter::kHeader, in its order.
  py::dict trace;
  trace["tick"] = column<std::uint64_t>(ticks, [](const HapticState& s) { return s.tick; });
  trace["t"] = column<double>(ticks, [](const HapticState& s) { return s.time; });
  trace["finger_x"] = column<double>(ticks, [](const HapticState& s) { return s.finger.x; });
  trace["finger_y"] = column<double>(ticks, [](const HapticState& s) { return s.finger.y; });
  trace["finger_z"] = column<double>(ticks, [](const HapticState& s) { return s.finger.z; });
  trace["proxy_x"] = column<double>(ticks, [](const HapticState& s) { return s.proxy.x; });
  trace["proxy_y"] = column<double>(ticks, [](const HapticState& s) { return s.proxy.y; });
  trace["proxy_z"] = column<double>(ticks, [](const HapticState& s) { return s.proxy.z; });
  trace["force_x"] = column<double>(ticks, [](const HapticState& s) { return s.force.x; });
  trace["force_y"] = column<double>(ticks, [](const HapticState& s) { return s.force.y; });
  trace["force_z"] = column<double>(ticks, [](const HapticState& s) { return s.force.z; });
  trace["contacts"] =
    column<std::int32_t>(ticks, [](const HapticState& s) { return s.numContacts; });
  trace["iterations"] =
    column<std::int32_t>(ticks, [](const HapticState& s) { return s.iterations; });
  trace["solve_ns"] =
    column<std::int64_t>(ticks, [](const HapticState& s) { return s.solveNanoseconds; });
  trace["object"] =
    column<std::int32_t>(ticks, [](const HapticState& s) { return s.contactObject; });
  trace["flags"] = column<std::uint32_t>(ticks, [](const HapticState& s) { return tickFlags(s); });
  return trace;
}

} // namespace proxima::python
