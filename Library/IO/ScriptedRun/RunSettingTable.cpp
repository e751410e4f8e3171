#include "IO/ScriptedRun/RunSettingTable.h"

#include "IO/ScriptedRun/ScriptedRunSettings.h"
#include "Runtime/TickBudget.h"

#include <algorithm>
#include <array>
#include <cstdio>

namespace proxima
{
namespace
{
using Kind = RunSettingKind;
using Scope = RunSettingScope;

// A row's member pointer goes to the field of its type; the others stay null.
constexpr RunSetting row(const char* option, Kind kind, Scope scope, int field, const char* help,
                         const ParameterRange* range, const char* choices,
                         double ScriptedRunSettings::*member)
{
  return {option, kind, scope, field, help, range, choices, member, nullptr, nullptr};
}

constexpr RunSetting row(const char* option, Kind kind, Scope scope, int field, const char* help,
                         const ParameterRange* range, const char* choices,
                         int ScriptedRunSettings::*member)
{
  return {option, kind, scope, field, help, range, choices, nullptr, member, nullptr};
}

constexpr RunSetting row(const char* option, Kind kind, Scope scope, int field, const char* help,
                         const ParameterRange* range, const char* choices,
                         std::string ScriptedRunSettings::*member)
{
  return {option, kind, scope, field, help, range, choices, nullptr, nullptr, member};
}

#define PROXIMA_RUN_SETTING_ROW(member, option, type, kind, byDefault, range, choices, scope,      \
                                field, help)                                                       \
  row(option, Kind::kind, Scope::scope, field, help, range, choices, &ScriptedRunSettings::member),

constexpr std::array kRows{PROXIMA_RUN_SETTINGS(PROXIMA_RUN_SETTING_ROW)};

#undef PROXIMA_RUN_SETTING_ROW

std::string fullNumber(double value)
{
  // 17 significant digits read back to the same double.
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

} // namespace

std::string RunSetting::keyword() const
{
  std::string name = option;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

std::string RunSetting::textOf(const ScriptedRunSettings& settings) const
{
  if (number != nullptr)
  {
    return fullNumber(settings.*number);
  }
  if (whole != nullptr)
  {
    return std::to_string(settings.*whole);
  }
  return settings.*text;
}

std::vector<std::string> RunSetting::choiceList() const
{
  std::vector<std::string> words;
  if (choices == nullptr)
  {
    return words;
  }
  std::string word;
  for (const char* c = choices;; ++c)
  {
    if (*c == '|' || *c == '\0')
    {
      words.push_back(word);
      word.clear();
      if (*c == '\0')
      {
        return words;
      }
    }
    else
    {
      word += *c;
    }
  }
}

std::string RunSetting::refusal(const ScriptedRunSettings& settings) const
{
  switch (kind)
  {
    case Kind::Number:
    case Kind::WholeNumber:
    {
      const double value = number != nullptr ? settings.*number : settings.*whole;
      return range->contains(value)
               ? std::string()
               : "must be " + describeRange(*range) + ", not " + shortNumber(value);
    }
    case Kind::NonZeroNumber:
    {
      // 0 is the knob not given (the rules between knobs ask for it where it is needed); the
      // command line refuses a 0 given on purpose.
      const double value = settings.*number;
      return value == 0.0 || range->contains(value)
               ? std::string()
               : "must be a number other than 0, " + describeRange(*range) + ", not " +
                   shortNumber(value);
    }
    case Kind::Choice:
    {
      const std::vector<std::string> words = choiceList();
      // Empty is the knob not given: the rules between knobs ask for it where it is needed.
      const std::string& value = settings.*text;
      if (value.empty() || std::find(words.begin(), words.end(), value) != words.end())
      {
        return {};
      }
      std::string names;
      for (const std::string& word : words)
      {
        names += names.empty() ? word : ", " + word;
      }
      return "'" + value + "' is not one of " + names;
    }
    case Kind::TickBudget:
    {
      TickWorkBudget ignored;
      return (settings.*text).empty() ? std::string() : parseTickBudget(settings.*text, ignored);
    }
    case Kind::File: return {};
  }
  return {};
}

std::span<const RunSetting> runSettings()
{
  return kRows;
}

const RunSetting* findRunSetting(const std::string& name)
{
  for (const RunSetting& setting : kRows)
  {
    if (name == setting.option || name == setting.keyword())
    {
      return &setting;
    }
  }
  return nullptr;
}

} // namespace proxima
