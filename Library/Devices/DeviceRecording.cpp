#include "Devices/DeviceRecording.h"

#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputError.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string_view>

namespace proxima
{

const char* const kDeviceRecordingHeader =
  "t,x,y,z,valid,connected,buttons,has_orientation,qw,qx,qy,qz";

namespace
{
constexpr std::size_t kNumColumns = 12;

bool parseDouble(const std::string& text, double& value)
{
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto [at, code] = std::from_chars(begin, end, value);
  return code == std::errc() && at == end;
}
} // namespace

bool writeDeviceRecording(const std::string& path, const std::vector<RecordedSample>& samples,
                          std::string& error)
{
  try
  {
    // All or nothing (AtomicOutputFile): a replay never reads a recording cut short.
    AtomicOutputFile file(path);
    file.write(kDeviceRecordingHeader);
    file.write("\n");
    char line[512];
    for (const RecordedSample& row : samples)
    {
      const DeviceSample& s = row.sample;
      // %.17g: every double comes back bit for bit.
      const int length = std::snprintf(
        line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%d,%d,%u,%d,%.17g,%.17g,%.17g,%.17g\n",
        row.time, s.position.x, s.position.y, s.position.z, s.valid ? 1 : 0, s.connected ? 1 : 0,
        static_cast<unsigned>(s.buttons), s.hasOrientation ? 1 : 0, s.orientation[0],
        s.orientation[1], s.orientation[2], s.orientation[3]);
      file.write(std::string_view(line, static_cast<std::size_t>(length)));
    }
    file.commit();
  }
  catch (const OutputError& failure)
  {
    error = failure.what();
    return false;
  }
  return true;
}

std::optional<std::vector<RecordedSample>> readDeviceRecording(const std::string& path,
                                                               std::string& error)
{
  std::ifstream file(path);
  if (!file)
  {
    error = path + ": cannot open the file";
    return std::nullopt;
  }
  std::string line;
  if (!std::getline(file, line) || line != kDeviceRecordingHeader)
  {
    error = path + ": line 1: the header must be '" + kDeviceRecordingHeader + "'";
    return std::nullopt;
  }
  std::vector<RecordedSample> samples;
  static const char* const names[kNumColumns] = {
    "t", "x", "y", "z", "valid", "connected", "buttons", "has_orientation", "qw", "qx", "qy", "qz"};
  for (std::size_t number = 2; std::getline(file, line); ++number)
  {
    if (line.empty())
    {
      continue;
    }
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, ',');)
    {
      fields.push_back(field);
    }
    const std::string where = path + ": line " + std::to_string(number) + ": ";
    if (fields.size() != kNumColumns)
    {
      error = where + "has " + std::to_string(fields.size()) + " values, not " +
              std::to_string(kNumColumns);
      return std::nullopt;
    }
    double values[kNumColumns];
    for (std::size_t i = 0; i < kNumColumns; ++i)
    {
      if (!parseDouble(fields[i], values[i]))
      {
        error = where + names[i] + " is not a number ('" + fields[i] + "')";
        return std::nullopt;
      }
    }
    for (std::size_t i : {4u, 5u, 7u})
    {
      if (values[i] != 0.0 && values[i] != 1.0)
      {
        error = where + names[i] + " must be 0 or 1, not '" + fields[i] + "'";
        return std::nullopt;
      }
    }
    if (!std::isfinite(values[0]))
    {
      error = where + "t is not finite";
      return std::nullopt;
    }
    if (!samples.empty() && values[0] < samples.back().time)
    {
      error = where + "t goes backwards (" + fields[0] + " after " +
              std::to_string(samples.back().time) + ")";
      return std::nullopt;
    }
    if (!(values[6] >= 0.0 && values[6] <= 4294967295.0 && values[6] == std::floor(values[6])))
    {
      error = where + "buttons must be a whole number from 0 to 2^32 - 1, not '" + fields[6] + "'";
      return std::nullopt;
    }
    RecordedSample row;
    row.time = values[0];
    // Positions may be non-finite on purpose: a recorded NaN finger replays as one.
    row.sample.position = {values[1], values[2], values[3]};
    row.sample.valid = values[4] != 0.0;
    row.sample.connected = values[5] != 0.0;
    row.sample.buttons = static_cast<std::uint32_t>(values[6]);
    row.sample.hasOrientation = values[7] != 0.0;
    row.sample.orientation = {values[8], values[9], values[10], values[11]};
    samples.push_back(row);
  }
  if (samples.empty())
  {
    error = path + ": has no samples";
    return std::nullopt;
  }
  return samples;
}

} // namespace proxima
