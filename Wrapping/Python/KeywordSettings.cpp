// Keywords to ScriptedRunSettings, finger paths from Python, and traces to numpy columns.
#include "Bindings.h"

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/ScriptedRun/RunSettingTable.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace proxima::python
{
namespace
{
// "str ('0.002')": the Python type and value a keyword was given, for its TypeError.
std::string given(const py::handle& value)
{
  return std::string(Py_TYPE(value.ptr())->tp_name) + " (" + py::repr(value).cast<std::string>() +
         ")";
}

// A number keyword takes an int or a float (numpy's too) and nothing else: not a bool (True is
// not 1 m), not a string ('0.002' is text, as it is to Python). Its range is checked with the
// command line's (checkScriptedRunSettings).
double numberFrom(const std::string& keyword, const py::handle& value)
{
  PyObject* object = value.ptr();
  const bool number =
    !PyBool_Check(object) && !PyUnicode_Check(object) && !PyBytes_Check(object) &&
    (PyFloat_Check(object) || PyIndex_Check(object) || py::hasattr(value, "__float__"));
  if (!number || py::isinstance<py::array>(value) ||
      py::isinstance(value, py::module_::import("numpy").attr("bool_")))
  {
    throw py::type_error("keyword '" + keyword + "' takes a number (an int or a float), not " +
                         given(value));
  }
  PyObject* converted = PyNumber_Float(object);
  if (converted == nullptr)
  {
    // An int too large for a double (10**400): no number of any range.
    PyErr_Clear();
    return std::numeric_limits<double>::infinity();
  }
  const double result = PyFloat_AsDouble(converted);
  Py_DECREF(converted);
  return result;
}

// A count takes an int (numpy's too), not a float (1.5 is no count of iterations) nor a bool;
// one outside the command line's range, 2**70 as well, is refused as the command line refuses it.
int wholeFrom(const RunSetting& setting, const py::handle& value)
{
  PyObject* object = value.ptr();
  if (PyBool_Check(object) || !PyIndex_Check(object) || py::isinstance<py::array>(value))
  {
    throw py::type_error("keyword '" + setting.keyword() + "' takes a whole number (an int), not " +
                         given(value));
  }
  const py::object count = py::reinterpret_steal<py::object>(PyNumber_Index(object));
  int overflow = 0;
  const long long whole = PyLong_AsLongLongAndOverflow(count.ptr(), &overflow);
  if (overflow != 0 || !setting.range->contains(static_cast<double>(whole)))
  {
    throw InputError(setting.flag(), "must be a whole number " + describeRange(*setting.range) +
                                       ", not " + py::str(count).cast<std::string>());
  }
  return static_cast<int>(whole);
}

// A text keyword: a path-like object (pathlib.Path) is taken as its string.
std::string textFrom(const py::handle& value)
{
  return py::str(value).cast<std::string>();
}

// The keyword `name`'s value into `settings`: the scene inputs, or a knob of the settings table
// (RunSettingTable.h), named as `proxima run` spells its option with '_' for '-'.
void setKeyword(ScriptedRunSettings& settings, const std::string& name, const py::handle& value)
{
  if (name == "mesh" || name == "scene")
  {
    (name == "mesh" ? settings.mesh : settings.scene) = textFrom(value);
    return;
  }
  const RunSetting* setting = findRunSetting(name);
  if (setting == nullptr || name != setting->keyword())
  {
    throw py::type_error("unexpected keyword '" + name +
                         "' (the keywords are proxima run's options, with _ for -)");
  }
  if (setting->number != nullptr)
  {
    settings.*setting->number = numberFrom(name, value);
  }
  else if (setting->whole != nullptr)
  {
    settings.*setting->whole = wholeFrom(*setting, value);
  }
  else
  {
    settings.*setting->text = textFrom(value);
  }
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
    setKeyword(settings, name, value);
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
  trace["flags"] =
    column<std::uint32_t>(ticks, [](const HapticState& s) { return s.conditions.bits(); });
  return trace;
}

} // namespace proxima::python
