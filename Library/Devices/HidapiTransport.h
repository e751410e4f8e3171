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

/// One HID device as hidapi enumerates it.
struct HidDeviceInfo
{
  /// The hidraw node, e.g. /dev/hidraw3: what openHidapiTransport takes.
  std::string path;
  /// USB (or Bluetooth) vendor ID.
  std::uint16_t vendorId = 0;
  /// Product ID within the vendor's range.
  std::uint16_t productId = 0;
  /// The manufacturer string, in ASCII (other characters become '?'); empty if none.
  std::string manufacturer;
  /// The product string, in ASCII (other characters become '?'); empty if none.
  std::string product;
  /// The USB interface the HID device belongs to; -1 where hidapi does not know it.
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
