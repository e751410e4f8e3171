#include "SceneOptions.h"

#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "IO/ScriptedRun/RunSettingTable.h"
#include "Runtime/ServoRate.h"

#include <string>
#include <vector>

namespace proxima::cli
{

static_assert(kRealtimeRateRange.low == kMinServoRate && kRealtimeRateRange.high == kMaxServoRate,
              "the real-time rate's range is the servo loop's rule");

namespace
{
// The knob's option, with the check its kind takes: `range` replaces the row's for --rate, whose
// range is the command's (a real-time servo loop has its own).
CLI::Option* addKnob(CLI::App& app, SceneOptions& options, const RunSetting& setting,
                     const std::string& helpPrefix, const ParameterRange* range = nullptr)
{
  const std::string help = helpPrefix + setting.help;
  const std::string flag = setting.flag();
  if (range == nullptr)
  {
    range = setting.range;
  }
  switch (setting.kind)
  {
    case RunSettingKind::Number:
      return app.add_option(flag, options.*setting.number, help)->check(numberIn(*range));
    case RunSettingKind::NonZeroNumber:
      return app.add_option(flag, options.*setting.number, help)
        ->check(CLI::Validator(
          [setting](std::string& input) -> std::string {
            double value = 0.0;
            return parsePlainNumber(input, value) && value != 0.0 && setting.range->contains(value)
                     ? std::string()
                     : "must be a number other than 0, " + describeRange(*setting.range) +
                         ", not " + input;
          },
          "NONZERO"));
    case RunSettingKind::WholeNumber:
      return app.add_option(flag, options.*setting.whole, help)->check(wholeNumberIn(*range));
    case RunSettingKind::Choice:
    {
      return app.add_option(flag, options.*setting.text, help)
        ->check(CLI::IsMember(setting.choiceList()));
    }
    case RunSettingKind::TickBudget:
      return app.add_option(flag, options.*setting.text, help)->check(tickBudgetValue());
    case RunSettingKind::File: return app.add_option(flag, options.*setting.text, help);
  }
  return nullptr;
}
} // namespace

void addSceneOptionsThroughPath(CLI::App& app, SceneOptions& options, bool pathRequired)
{
  CLI::Option* mesh = app.add_option("--mesh", options.mesh,
                                     "Mesh file (STL, OBJ, PLY, VTP, OFF, glTF/GLB); or --scene");
  CLI::Option* scene = app.add_option(
    "--scene", options.scene,
    "Scene file (JSON: objects with meshes, poses and materials; Documentation/SceneFiles.md); "
    "the surface options below are then the file's, per object");
  mesh->excludes(scene);
  for (const RunSetting& setting : runSettings())
  {
    if (setting.scope == RunSettingScope::Proxy)
    {
      addKnob(app, options, setting, "");
    }
  }
  CLI::Option* path = app.add_option("--path", options.path, "Finger path CSV (t,x,y,z)");
  if (pathRequired)
  {
    path->required();
  }
}

void addSceneOptionsAfterPath(CLI::App& app, SceneOptions& options, const ParameterRange& rateRange)
{
  for (const RunSetting& setting : runSettings())
  {
    if (setting.scope == RunSettingScope::Servo)
    {
      addKnob(app, options, setting, "",
              setting.number == &SceneOptions::rate ? &rateRange : nullptr);
    }
  }
  // The mesh's scale and surface: for --mesh only (a scene file gives them per object), and
  // --texture's knobs need --texture and it them.
  CLI::Option* scene = app.get_option("--scene");
  CLI::Option* texture = nullptr;
  std::vector<CLI::Option*> textureKnobs;
  for (const RunSetting& setting : runSettings())
  {
    if (setting.scope != RunSettingScope::Surface)
    {
      continue;
    }
    CLI::Option* option = addKnob(app, options, setting, "With --mesh only. ");
    scene->excludes(option);
    if (setting.text == &SceneOptions::texture)
    {
      texture = option;
    }
    else if (std::string(setting.option).rfind("texture-", 0) == 0)
    {
      textureKnobs.push_back(option);
    }
  }
  for (CLI::Option* knob : textureKnobs)
  {
    knob->needs(texture);
  }
  texture->needs(app.get_option("--texture-role"));
}

void addTickBudgetOption(CLI::App& app, SceneOptions& options, const std::string& defaults)
{
  const RunSetting& budget = *findRunSetting("tick-budget");
  addKnob(app, options, budget, "")
    ->description(std::string(budget.help) + " The real-time default is " +
                  std::to_string(kDefaultTickBudgetIterations) + "it. " + defaults);
}

void checkSceneOptions(const SceneOptions& options, const CLI::App& /*app*/)
{
  if (options.mesh.empty() && options.scene.empty())
  {
    throw CLI::RequiredError("--mesh or --scene");
  }
  // The values' own ranges are the options' validators'; what is left are the rules between
  // options, which the library words the same way for every caller (a usage error here).
  try
  {
    checkScriptedRunSettings(options);
  }
  catch (const InputError& error)
  {
    throw CLI::ValidationError(error.path(), error.defect());
  }
}

} // namespace proxima::cli
