// Writes proxima_run_settings.proto, the RunSettings message of remote runs, from the settings
// table (IO/ScriptedRun/RunSettingList.h): one field per knob, named as Python's keyword and
// numbered as the row says, so that a new knob reaches the wire without an edit here. Run by the
// build (Library/Net/CMakeLists.txt) before protoc; fails on a field number used twice, so that
// a row cannot silently take another's place on the wire.
#include "IO/ScriptedRun/RunSettingList.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <string>

namespace
{
// The .proto type of a row's C++ type.
template <typename T>
const char* protoType();
template <>
const char* protoType<double>()
{
  return "double";
}
template <>
const char* protoType<int>()
{
  return "int32";
}
template <>
const char* protoType<std::string>()
{
  return "string";
}

// The request's own limit, not a knob of the run: it keeps the number it had before the table.
constexpr int kMaxTicksField = 17;

struct Field
{
  std::string option;
  const char* type;
  int number;
};
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: proxima-run-settings-proto OUT.proto\n";
    return 2;
  }
  const Field rows[] = {
#define PROXIMA_RUN_SETTING_FIELD(member, option, type, kind, byDefault, range, choices, scope,    \
                                  field, help)                                                     \
  {option, protoType<type>(), field},
    PROXIMA_RUN_SETTINGS(PROXIMA_RUN_SETTING_FIELD)
#undef PROXIMA_RUN_SETTING_FIELD
  };
  std::string message;
  std::set<int> numbers{kMaxTicksField};
  for (const Field& row : rows)
  {
    if (row.number == 0)
    {
      continue; // a file: its bytes travel in the request, not its name
    }
    if (!numbers.insert(row.number).second)
    {
      std::cerr << "RunSettingList.h: --" << row.option << " takes field number " << row.number
                << ", which another field has\n";
      return 1;
    }
    std::string name = row.option;
    for (char& c : name)
    {
      c = c == '-' ? '_' : c;
    }
    message +=
      "  " + std::string(row.type) + " " + name + " = " + std::to_string(row.number) + ";\n";
  }
  const std::string text =
    "// Generated from Library/IO/ScriptedRun/RunSettingList.h by Library/Net/Generate/"
    "RunSettingsProto.cpp: edit the table, not this file.\n"
    "syntax = \"proto3\";\n\npackage proxima.net;\n\n"
    "// The knobs of a remote run, as ScriptedRunSettings holds them.\n"
    "message RunSettings {\n" +
    message +
    "  // The client's --max-ticks: a limit of the request, not a knob of the run.\n"
    "  double max_ticks = " +
    std::to_string(kMaxTicksField) + ";\n}\n";
  // Written whole under another name and renamed, so that a failed write leaves no half file
  // for protoc to read.
  const std::string temporary = std::string(argv[1]) + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush())
    {
      std::cerr << "cannot write " << temporary << "\n";
      return 1;
    }
  }
  if (std::rename(temporary.c_str(), argv[1]) != 0)
  {
    std::cerr << "cannot rename " << temporary << " to " << argv[1] << "\n";
    return 1;
  }
  return 0;
}
