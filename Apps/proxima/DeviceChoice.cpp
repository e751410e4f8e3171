#include "DeviceChoice.h"

#include "Devices/DeviceRegistry.h"
#include "IO/InputChecks/InputError.h"

namespace proxima::cli
{
namespace
{
// The registry's errors read "<what>: <defect>"; InputError wants the two apart.
[[noreturn]] void throwDeviceError(const std::string& error)
{
  const std::size_t colon = error.find(": ");
  if (colon == std::string::npos)
  {
    throw InputError("--device", error);
  }
  throw InputError(error.substr(0, colon), error.substr(colon + 2));
}
} // namespace

void addDeviceOptions(CLI::App& app, DeviceChoiceOptions& options)
{
  app
    .add_option("--device", options.device,
                std::string("The finger's device: ") + kDeviceNames +
                  " (default sim: the --path; Documentation/Devices.md)")
    ->check(CLI::Validator(
      [](std::string& input) -> std::string {
        return isDeviceSpec(input)
                 ? std::string()
                 : "must be one of " + std::string(kDeviceNames) + ", not " + input;
      },
      "DEVICE"));
  app.add_option("--falcon-firmware", options.falconFirmware,
                 "With --device falcon: the firmware file to upload (your own copy; not shipped)");
  app.add_option("--record-device", options.recordDevice,
                 "Record the device's samples to this file, for --device replay:FILE");
}

RunDevice::RunDevice(const DeviceChoiceOptions& options, const FingerPath& path,
                     std::size_t numTicks)
  : m_options(options)
{
  DeviceOptions deviceOptions;
  deviceOptions.path = path;
  deviceOptions.falconFirmware = options.falconFirmware;
  std::string error;
  m_device = openDevice(options.device, deviceOptions, error);
  if (!m_device)
  {
    throwDeviceError(error);
  }
  if (!options.recordDevice.empty())
  {
    m_recorder = std::make_unique<RecordingDevice>(*m_device, numTicks);
  }
}

HapticDevice& RunDevice::device()
{
  return m_recorder ? static_cast<HapticDevice&>(*m_recorder) : *m_device;
}

void RunDevice::finish()
{
  if (!m_recorder)
  {
    return;
  }
  std::string error;
  if (!writeDeviceRecording(m_options.recordDevice, m_recorder->samples(), error))
  {
    throwDeviceError(error);
  }
}

} // namespace proxima::cli
