// A recorded device session: one row per servo tick with the time and the sample the device gave
// (position, validity, connection, buttons, orientation). Written by RecordingDevice, played back
// by ReplayDevice; the file format (CSV, Documentation/Devices.md) round-trips every double
// exactly, so a replayed run's trace equals the recorded run's.
#pragma once

#include "Runtime/HapticDevice.h"

#include <optional>
#include <string>
#include <vector>

namespace proxima
{

/// One row of a recording: what the device reported for the servo tick at `time`.
struct RecordedSample
{
  /// The tick's time (s, on the runtime's clock); never decreases along a recording.
  double time = 0.0;
  /// The sample the device returned for that tick, non-finite positions included.
  DeviceSample sample;
};

/// The header line of a recording file.
extern const char* const kDeviceRecordingHeader;

/// Writes `samples` to `path`; false with `error` ("<path>: <defect>") if the file cannot be
/// written.
bool writeDeviceRecording(const std::string& path, const std::vector<RecordedSample>& samples,
                          std::string& error);

/// Reads a recording; nullopt with `error` ("<path>: line N: <defect>") for a missing file, a
/// wrong header, a short row, a value that is not a number, a non-finite time, or times that go
/// backwards.
std::optional<std::vector<RecordedSample>> readDeviceRecording(const std::string& path,
                                                               std::string& error);

} // namespace proxima
