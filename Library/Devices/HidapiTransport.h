// HID reports through hidapi's hidraw backend (hidapi 0.13), and the device's report descriptor
// from sysfs, which hidapi 0.13 cannot read. The hidapi headers stay in the .cpp file.
#pragma once

#include "Devices/DeviceTransport.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace proxima
{

struct HidDeviceInfo
{
  /// The hidraw node, e.g. /dev/hidraw3: what openHidapiTransport takes.
  std::string path;
  std::uint16_t vendorId = 0;
  std::uint16_t productId = 0;
  std::string manufacturer;
  std::string product;
  int interfaceNumber = -1;
};

/// Every HID device hidapi sees (vendorId 0: any vendor).
std::vector<HidDeviceInfo> enumerateHidDevices(std::uint16_t vendorId = 0);

/// Opens the hidraw node at `path`; nullptr with `error` if it cannot be opened (missing,
/// no permission: see the udev rules in Documentation/Devices.md).
std::unique_ptr<ReportTransport> openHidapiTransport(const std::string& path, std::string& error);

/// The report descriptor of the hidraw node at `path` (/dev/hidrawN), read from
/// /sys/class/hidraw/hidrawN/device/report_descriptor; nullopt with `error` if absent or empty.
std::optional<std::vector<std::uint8_t>> readHidReportDescriptor(const std::string& path,
                                                                 std::string& error);

} // namespace proxima
