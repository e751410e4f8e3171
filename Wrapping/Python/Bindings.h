// The pieces of the Python module `proxima._proxima` (one file each), and what they share: the
// keywords of `proxima run`'s options read into ScriptedRunSettings, and finger paths from a
// file name or a numpy array. pybind11 stays in this folder; the library does not see it.
#pragma once

#include "IO/ScriptedRun/ScriptedRunSettings.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticState.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace proxima::python
{
namespace py = pybind11;

/// Settings from keywords named as `proxima run`'s options with '_' for '-' (max_force=...);
/// None means the option's default, any other unknown keyword is a TypeError. The values are
/// checked (checkScriptedRunSettings) and InputError names the option.
ScriptedRunSettings settingsFromKeywords(const py::kwargs& keywords);

/// A finger path from a CSV file name (read as `proxima run --path` reads it; `settings.path`
/// becomes the name) or from an (N, 4) array of rows t, x, y, z (`settings.path` becomes
/// "path array"), checked the same way: finite values, time never going backwards.
FingerPath fingerPathFrom(const py::object& path, ScriptedRunSettings& settings);
/// An (N, 4) float64 array of rows t, x, y, z.
py::array_t<double> fingerPathArray(const FingerPath& path);
/// A point or vector as a float64 array of 3: x, y, z.
py::array_t<double> vectorArray(const Vec3& v);

/// The ticks as named numpy columns, in the order and with the values of trace v2's CSV columns.
py::dict traceColumns(const std::vector<HapticState>& ticks);

void addRunBindings(py::module_& module);
void addPathBindings(py::module_& module);
void addSessionBindings(py::module_& module);
void addOracleBindings(py::module_& module);
void addHapticClientBindings(py::module_& module);

} // namespace proxima::python
