// The FTDI serial bridge of a USB device through libusb: FTDI vendor requests on the control
// endpoint, payload on the bulk endpoints, the two modem-status bytes of every IN packet
// stripped. The libusb headers stay in the .cpp file.
#pragma once

#include "Devices/DeviceTransport.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace proxima
{

/// One USB device as libusb enumerates it.
struct UsbDeviceInfo
{
  /// Vendor ID from the device descriptor.
  std::uint16_t vendorId = 0;
  /// Product ID from the device descriptor.
  std::uint16_t productId = 0;
  /// Number of the USB bus the device is on.
  int bus = 0;
  /// The device's address on that bus.
  int address = 0;
};

/// The USB devices libusb sees with this vendor and product ID (0: any).
std::vector<UsbDeviceInfo> enumerateUsbDevices(std::uint16_t vendorId, std::uint16_t productId);

/// Opens the first device with this vendor and product, claims interface 0 (detaching a kernel
/// driver such as ftdi_sio first); nullptr with `error` if there is none or it cannot be opened.
std::unique_ptr<BulkTransport> openFtdiTransport(std::uint16_t vendorId, std::uint16_t productId,
                                                 std::string& error);

} // namespace proxima
