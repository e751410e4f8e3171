// proxima._proxima: the compiled half of the Python package `proxima` (its __init__.py is the
// other half). Errors the library names (a file, an option) arrive in Python as
// proxima.InputError, a ValueError, with the same one-line message as the command line's.
#include "Bindings.h"

#include "Core/TickConditions.h"
#include "IO/InputChecks/InputError.h"
#include "IO/Output/OutputError.h"

PYBIND11_MODULE(_proxima, module)
{
  namespace python = proxima::python;
  module.doc() = "Proxima's haptic rendering kernel: scripted runs, sessions, paths and the oracle";
  pybind11::register_exception<proxima::InputError>(module, "InputError", PyExc_ValueError);
  pybind11::register_exception<proxima::OutputError>(module, "OutputError", PyExc_OSError);
  python::addRunBindings(module);
  python::addPathBindings(module);
  python::addSessionBindings(module);
  // The bit of each tick condition in a trace's and a message's `flags`, by name.
  pybind11::dict conditions;
  for (const proxima::TickConditionName& entry : proxima::kTickConditionNames)
  {
    conditions[entry.name] = static_cast<std::uint32_t>(entry.condition);
  }
  module.attr("tick_conditions") = conditions;
#if PROXIMA_PYTHON_NET
  python::addHapticClientBindings(module);
#endif
#if PROXIMA_PYTHON_ORACLE
  python::addOracleBindings(module);
#endif
}
