// proxima._proxima.run: a scripted run in lockstep, as `proxima run` plays it (IO/ScriptedRun).
#include "Bindings.h"

#include "IO/InputChecks/ParameterRanges.h"
#include "IO/ScriptedRun/RunSettingTable.h"
#include "IO/ScriptedRun/ScriptedRun.h"

namespace proxima::python
{

void addRunBindings(py::module_& module)
{
  module.def(
    "run",
    [](const py::object& path, double maxTicks, const py::kwargs& keywords) {
      ScriptedRunSettings settings = settingsFromKeywords(keywords);
      const FingerPath fingerPath = fingerPathFrom(path, settings);
      ScriptedRunResult result;
      {
        // Other Python threads (a Dask worker's) go on while the path plays.
        py::gil_scoped_release released;
        result = runScriptedPath(settings, fingerPath, maxTicks);
      }
      return py::make_tuple(traceColumns(result.ticks), result.summaryJson);
    },
    py::arg("path"), py::arg("max_ticks") = kDefaultMaxTicks,
    "Plays `path` (a CSV file name or an (N, 4) array t, x, y, z) in lockstep through the mesh "
    "or scene of the keywords (proxima run's options, _ for -). Returns (trace columns, summary "
    "JSON text).");
  // The knobs the keywords set, from the settings table: keyword -> (the command line's option,
  // the default as it spells it, the help).
  py::dict knobs;
  const ScriptedRunSettings defaults;
  for (const RunSetting& setting : runSettings())
  {
    knobs[py::str(setting.keyword())] =
      py::make_tuple(setting.flag(), setting.textOf(defaults), setting.help);
  }
  module.attr("run_settings") = knobs;
}

} // namespace proxima::python
