// The remote run's settings on the wire: every knob of the settings table, set away from its
// default, goes through RunSettings (serialized and parsed, as gRPC carries it) and comes back
// with the same value, bit for bit; the generated message has exactly the table's fields.
#include "IO/ScriptedRun/RunSettingTable.h"
#include "Net/Private/RunSettingsMessage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace proxima
{
namespace
{

// Every knob away from its default, numbers with all 17 digits in use.
ScriptedRunSettings everyKnobChanged()
{
  ScriptedRunSettings settings;
  double salt = 0.1;
  for (const RunSetting& setting : runSettings())
  {
    salt += 0.01;
    if (setting.number != nullptr)
    {
      settings.*setting.number = std::nextafter(settings.*setting.number + salt, 1e9);
    }
    else if (setting.whole != nullptr)
    {
      settings.*setting.whole += 7;
    }
    else if (setting.kind != RunSettingKind::File)
    {
      settings.*setting.text = std::string("value of ") + setting.option;
    }
  }
  return settings;
}

TEST(RunSettingsMessage, EveryKnobCrossesTheWireUnchanged)
{
  const ScriptedRunSettings sent = everyKnobChanged();
  net::RunSettings message;
  detail::writeRunSettings(sent, message);
  message.set_max_ticks(123.0);
  net::RunSettings parsed;
  ASSERT_TRUE(parsed.ParseFromString(message.SerializeAsString()));
  ScriptedRunSettings received;
  detail::readRunSettings(parsed, received);
  const ScriptedRunSettings defaults;
  for (const RunSetting& setting : runSettings())
  {
    if (setting.kind == RunSettingKind::File)
    {
      EXPECT_EQ(setting.textOf(received), setting.textOf(defaults)) << setting.option;
      continue;
    }
    EXPECT_NE(setting.textOf(sent), setting.textOf(defaults)) << setting.option;
    EXPECT_EQ(setting.textOf(received), setting.textOf(sent)) << setting.option;
  }
  EXPECT_EQ(parsed.max_ticks(), 123.0);
}

TEST(RunSettingsMessage, TheMessageHasTheTablesFieldsAndMaxTicks)
{
  std::set<std::string> expected{"max_ticks"};
  for (const RunSetting& setting : runSettings())
  {
    if (setting.kind != RunSettingKind::File)
    {
      expected.insert(setting.keyword());
      const auto* field = net::RunSettings::descriptor()->FindFieldByName(setting.keyword());
      ASSERT_NE(field, nullptr) << setting.keyword();
      EXPECT_EQ(field->number(), setting.field) << setting.keyword();
    }
  }
  std::set<std::string> fields;
  const auto* descriptor = net::RunSettings::descriptor();
  for (int i = 0; i < descriptor->field_count(); ++i)
  {
    fields.insert(descriptor->field(i)->name());
  }
  EXPECT_EQ(fields, expected);
}

} // namespace
} // namespace proxima
