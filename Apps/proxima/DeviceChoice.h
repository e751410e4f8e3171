// The device of a `proxima run`: the options that choose it (--device, --falcon-firmware,
// --record-device), and the device they name, with its session recorded to a file when asked.
// Kept out of RunCommand.cpp so that the commands sharing run's options share these too.
#pragma once

#include "Devices/ReplayDevice.h"
#include "Runtime/FingerPath.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace proxima::cli
{

struct DeviceChoiceOptions
{
  std::string device = "sim";
  std::string falconFirmware;
  std::string recordDevice;
};

/// Registers --device, --falcon-firmware and --record-device on `app`.
void addDeviceOptions(CLI::App& app, DeviceChoiceOptions& options);

class RunDevice
{
public:
  /// Opens the chosen device; throws InputError (one line naming the device or file and the
  /// defect) if it cannot. `path` is the scripted path (sim) and the workspace centre (others).
  RunDevice(const DeviceChoiceOptions& options, const FingerPath& path, std::size_t numTicks);
  /// What the servo reads: the device, or its recorder when --record-device is given.
  HapticDevice& device();
  /// The device itself, under its recorder if any (the view aims a mouse's).
  HapticDevice& openedDevice() { return *m_device; }
  /// Writes the recording (--record-device); throws InputError if the file cannot be written.
  void finish();

private:
  DeviceChoiceOptions m_options;
  std::unique_ptr<HapticDevice> m_device;
  std::unique_ptr<RecordingDevice> m_recorder;
};

} // namespace proxima::cli
