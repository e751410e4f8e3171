// The settings table against what its rows promise: names and wire numbers unique, every knob's
// default accepted, every number knob refused just outside its range (and accepted at its ends)
// with the option named, values that read back bit for bit from their text, and each knob a
// member of its own (no two rows write the same field).
#include "IO/InputChecks/InputError.h"
#include "IO/ScriptedRun/RunSettingTable.h"
#include "IO/ScriptedRun/ScriptedRunSettings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>
#include <string>

namespace proxima
{
namespace
{

ScriptedRunSettings meshRun()
{
  ScriptedRunSettings settings;
  settings.mesh = "part.stl";
  return settings;
}

// The message checkScriptedRunSettings throws for `settings`, or "" when it accepts them.
std::string refusalOf(const ScriptedRunSettings& settings)
{
  try
  {
    checkScriptedRunSettings(settings);
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return {};
}

TEST(RunSettingTable, NamesAndFieldNumbersAreUnique)
{
  std::set<std::string> options;
  std::set<std::string> keywords;
  std::set<int> fields;
  for (const RunSetting& setting : runSettings())
  {
    EXPECT_TRUE(options.insert(setting.option).second) << setting.option;
    EXPECT_TRUE(keywords.insert(setting.keyword()).second) << setting.option;
    EXPECT_EQ(setting.keyword().find('-'), std::string::npos) << setting.option;
    if (setting.kind == RunSettingKind::File)
    {
      EXPECT_EQ(setting.field, 0) << setting.option << ": a file's bytes travel, not its name";
    }
    else
    {
      EXPECT_GT(setting.field, 0) << setting.option;
      EXPECT_TRUE(fields.insert(setting.field).second) << setting.option << " " << setting.field;
    }
    EXPECT_EQ(findRunSetting(setting.option), &setting);
    EXPECT_EQ(findRunSetting(setting.keyword()), &setting);
    EXPECT_NE(std::string(setting.help), "") << setting.option;
  }
  EXPECT_EQ(findRunSetting("no-such-knob"), nullptr);
}

TEST(RunSettingTable, EachRowHasItsOwnMemberOfTheKindItsValueNeeds)
{
  // Writing one knob changes its own text and no other row's: no two rows share a member.
  const ScriptedRunSettings defaults = meshRun();
  for (const RunSetting& setting : runSettings())
  {
    const int members =
      (setting.number != nullptr) + (setting.whole != nullptr) + (setting.text != nullptr);
    ASSERT_EQ(members, 1) << setting.option;
    const bool numberKind =
      setting.kind == RunSettingKind::Number || setting.kind == RunSettingKind::NonZeroNumber;
    EXPECT_EQ(numberKind, setting.number != nullptr) << setting.option;
    EXPECT_EQ(setting.kind == RunSettingKind::WholeNumber, setting.whole != nullptr)
      << setting.option;
    EXPECT_EQ(setting.range != nullptr, numberKind || setting.whole != nullptr) << setting.option;
    EXPECT_EQ(setting.kind == RunSettingKind::Choice, setting.choices != nullptr) << setting.option;

    ScriptedRunSettings changed = defaults;
    if (setting.number != nullptr)
    {
      changed.*setting.number += 0.5;
    }
    else if (setting.whole != nullptr)
    {
      changed.*setting.whole += 1;
    }
    else
    {
      changed.*setting.text += "x";
    }
    for (const RunSetting& other : runSettings())
    {
      EXPECT_EQ(other.textOf(changed) == other.textOf(defaults), &other != &setting)
        << "writing " << setting.option << " changed " << other.option;
    }
  }
}

TEST(RunSettingTable, TheDefaultsAreAccepted)
{
  EXPECT_EQ(refusalOf(meshRun()), "");
  for (const RunSetting& setting : runSettings())
  {
    EXPECT_EQ(setting.refusal(meshRun()), "") << setting.option;
  }
}

TEST(RunSettingTable, EveryNumberIsRefusedJustOutsideItsRangeByItsOption)
{
  for (const RunSetting& setting : runSettings())
  {
    if (setting.range == nullptr)
    {
      continue;
    }
    const ParameterRange& range = *setting.range;
    const auto set = [&](ScriptedRunSettings& settings, double value) {
      if (setting.number != nullptr)
      {
        settings.*setting.number = value;
      }
      else
      {
        settings.*setting.whole = static_cast<int>(value);
      }
    };
    // A step out of the range that the member's type can hold.
    const double step = setting.whole != nullptr ? 1.0 : std::max(1e-9, range.high * 1e-9);
    ScriptedRunSettings above = meshRun();
    set(above, range.high + step);
    const std::string refused = setting.refusal(above);
    EXPECT_NE(refused.find("must be"), std::string::npos) << setting.option << ": " << refused;
    ScriptedRunSettings nan = meshRun();
    if (setting.number != nullptr)
    {
      set(nan, std::numeric_limits<double>::quiet_NaN());
      EXPECT_NE(setting.refusal(nan), "") << setting.option;
    }
    ScriptedRunSettings top = meshRun();
    set(top, range.high);
    EXPECT_EQ(setting.refusal(top), "") << setting.option;
    ScriptedRunSettings bottom = meshRun();
    set(bottom, range.lowExcluded ? range.low : range.low - step);
    if (setting.kind != RunSettingKind::NonZeroNumber || bottom.*setting.number != 0.0)
    {
      EXPECT_NE(setting.refusal(bottom), "") << setting.option;
    }
  }
  // And the whole check names the option the value came from.
  ScriptedRunSettings settings = meshRun();
  settings.maxForce = 1e9;
  EXPECT_EQ(refusalOf(settings).rfind("--max-force:", 0), 0u) << refusalOf(settings);
}

TEST(RunSettingTable, ChoicesAndBudgetsRefuseWordsTheyDoNotKnow)
{
  ScriptedRunSettings settings = meshRun();
  settings.shading = "sometimes";
  EXPECT_EQ(findRunSetting("shading")->refusal(settings),
            "'sometimes' is not one of off, on, auto");
  settings = meshRun();
  settings.tickBudget = "fast";
  EXPECT_NE(findRunSetting("tick_budget")->refusal(settings), "");
  settings.tickBudget = "16it";
  EXPECT_EQ(findRunSetting("tick_budget")->refusal(settings), "");
}

TEST(RunSettingTable, NumbersReadBackBitForBitFromTheirText)
{
  ScriptedRunSettings settings = meshRun();
  settings.radius = 0.1 + 0.2; // not a short decimal
  settings.stiffness = std::nextafter(1000.0, 2000.0);
  for (const RunSetting& setting : runSettings())
  {
    if (setting.number != nullptr)
    {
      const std::string text = setting.textOf(settings);
      EXPECT_EQ(std::strtod(text.c_str(), nullptr), settings.*setting.number) << setting.option;
    }
  }
}

TEST(RunSettingTable, ASceneRunLeavesTheSurfaceKnobsToTheFile)
{
  // --scene excludes the surface knobs on the command line; a caller that set one anyway is not
  // refused for it (the file's objects give the surface), but the run's own knobs still are.
  ScriptedRunSettings settings;
  settings.scene = "scene.json";
  settings.featureAngle = 500.0;
  EXPECT_EQ(refusalOf(settings), "");
  settings.radius = -1.0;
  EXPECT_EQ(refusalOf(settings).rfind("--radius:", 0), 0u) << refusalOf(settings);
}

} // namespace
} // namespace proxima
