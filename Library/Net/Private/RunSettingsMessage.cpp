#include "Net/Private/RunSettingsMessage.h"

#include "IO/ScriptedRun/RunSettingTable.h"

#include <stdexcept>

namespace proxima::detail
{
namespace
{
using google::protobuf::FieldDescriptor;

// The message's field of a knob, or nullptr for a file (whose bytes travel in the request).
// The generated .proto has a field for every other row (Net/Generate/RunSettingsProto.cpp), so a
// missing one is a build that mixes two tables: a programming error, not the user's.
const FieldDescriptor* fieldOf(const RunSetting& setting)
{
  if (setting.kind == RunSettingKind::File)
  {
    return nullptr;
  }
  const FieldDescriptor* field = net::RunSettings::descriptor()->FindFieldByName(setting.keyword());
  if (field == nullptr || field->number() != setting.field)
  {
    throw std::logic_error("RunSettings has no field " + std::to_string(setting.field) + " " +
                           setting.keyword());
  }
  return field;
}
} // namespace

void writeRunSettings(const ScriptedRunSettings& settings, net::RunSettings& message)
{
  const google::protobuf::Reflection* reflection = message.GetReflection();
  for (const RunSetting& setting : runSettings())
  {
    const FieldDescriptor* field = fieldOf(setting);
    if (field == nullptr)
    {
      continue;
    }
    if (setting.number != nullptr)
    {
      reflection->SetDouble(&message, field, settings.*setting.number);
    }
    else if (setting.whole != nullptr)
    {
      reflection->SetInt32(&message, field, settings.*setting.whole);
    }
    else
    {
      reflection->SetString(&message, field, settings.*setting.text);
    }
  }
}

void readRunSettings(const net::RunSettings& message, ScriptedRunSettings& settings)
{
  const google::protobuf::Reflection* reflection = message.GetReflection();
  for (const RunSetting& setting : runSettings())
  {
    const FieldDescriptor* field = fieldOf(setting);
    if (field == nullptr)
    {
      continue;
    }
    if (setting.number != nullptr)
    {
      settings.*setting.number = reflection->GetDouble(message, field);
    }
    else if (setting.whole != nullptr)
    {
      settings.*setting.whole = reflection->GetInt32(message, field);
    }
    else
    {
      settings.*setting.text = reflection->GetString(message, field);
    }
  }
}

} // namespace proxima::detail
