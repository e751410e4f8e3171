// The settings table: one row per knob of a scripted run (RunSettingList.h), with what every
// front needs to read, check and pass the knob on without a list of its own. The command line
// registers `--<option>` from a row, the Python module the keyword `<option with _>`, and the
// remote-run client and server copy the field `<option with _>` of RunSettings by it.
#pragma once

#include "IO/InputChecks/ParameterRanges.h"

#include <span>
#include <string>
#include <vector>

namespace proxima
{

struct ScriptedRunSettings;

/// How a knob's value is read and checked.
enum class RunSettingKind
{
  /// A decimal number within the row's range.
  Number,
  /// A number within the row's range and not 0 (--texture-amplitude: 0 would be no bump at all).
  NonZeroNumber,
  /// A whole number (a count) within the row's range.
  WholeNumber,
  /// One of the row's words; empty means not given.
  Choice,
  /// A tick budget as parseTickBudget reads it; empty means the caller's default.
  TickBudget,
  /// A file name. The remote-run client sends the file's bytes, not the name, so it has no field.
  File,
};

/// Which part of the run a knob belongs to: the command line registers them in this order, and
/// a scene file gives the Surface knobs per object instead (--scene excludes them).
enum class RunSettingScope
{
  Proxy,   ///< The proxy and the spring.
  Servo,   ///< The loop and the force.
  Surface, ///< The one object of a --mesh run.
  Budget,  ///< The tick's work budget.
};

/// One knob. Exactly one of `number`, `whole` and `text` is set, by `kind`.
struct RunSetting
{
  /// The command line's spelling without "--": "max-force".
  const char* option;
  /// How the value is read and checked.
  RunSettingKind kind;
  /// Which part of the run the knob belongs to.
  RunSettingScope scope;
  /// The field number of RunSettings in proxima_run_settings.proto; 0 for a File.
  int field;
  /// The command line's help text, also the Python documentation's.
  const char* help;
  /// Number kinds: the accepted range.
  const ParameterRange* range;
  /// Choice: the accepted words, separated by '|'.
  const char* choices;
  /// The knob's member of ScriptedRunSettings if it is a double (Number, NonZeroNumber); else
  /// null.
  double ScriptedRunSettings::*number;
  /// The knob's member if it is an int (WholeNumber); else null.
  int ScriptedRunSettings::*whole;
  /// The knob's member if it is a string (Choice, TickBudget, File); else null.
  std::string ScriptedRunSettings::*text;

  /// "max_force": Python's keyword and the .proto's field name.
  std::string keyword() const;
  /// "--max-force": what messages about the knob name.
  std::string flag() const { return std::string("--") + option; }
  /// The value of this knob in `settings`, as the command line would spell it (numbers in full
  /// precision, so that reading it back gives the same bits).
  std::string textOf(const ScriptedRunSettings& settings) const;
  /// Empty when this knob's value in `settings` is one it accepts, else why not ("must be above 0
  /// and at most 1 m, not 2"): the words the command line, Python and the server refuse it with.
  std::string refusal(const ScriptedRunSettings& settings) const;
  /// The accepted words of a Choice, in the row's order.
  std::vector<std::string> choiceList() const;
};

/// The rows of RunSettingList.h, in its order.
std::span<const RunSetting> runSettings();
/// The row whose option (`--max-force` without the dashes) or keyword (`max_force`) is `name`,
/// or nullptr.
const RunSetting* findRunSetting(const std::string& name);

} // namespace proxima
