// Devices by name, as `proxima run --device` and `proxima devices` take them: sim (the scripted
// finger path), replay:FILE (a recording), mouse (a pointer in a window aims the finger:
// PointerDevice), spacemouse (the first 3Dconnexion device hidapi sees),
// falcon (the first Novint Falcon libusb sees). Opening a real device never throws: a device that
// is absent, inaccessible or without its firmware gives nullptr and a one-line reason.
#pragma once

#include "Runtime/FingerPath.h"
#include "Runtime/HapticDevice.h"

#include <memory>
#include <string>
#include <vector>

namespace proxima
{

/// What openDevice() needs beyond the device name.
struct DeviceOptions
{
  /// The scripted path (sim) and, for the other devices, where their workspace centre goes in
  /// the world: the path's first position.
  FingerPath path;
  /// The Falcon firmware file the user supplies.
  std::string falconFirmware;
};

/// The names `--device` accepts, for help texts.
extern const char* const kDeviceNames;

/// True if `spec` names a device kind (its arguments are checked when it is opened).
bool isDeviceSpec(const std::string& spec);

/// Opens the device `spec` names; nullptr with `error` ("<what>: <defect>") if it cannot.
std::unique_ptr<HapticDevice> openDevice(const std::string& spec, const DeviceOptions& options,
                                         std::string& error);

/// A real device found by listConnectedDevices(), for `proxima devices` to print.
struct ConnectedDevice
{
  /// The --device name that opens it.
  std::string name;
  /// One line: vendor:product, product string, node or bus address.
  std::string description;
};

/// The real devices connected now (SpaceMice over hidraw, Falcons over USB).
std::vector<ConnectedDevice> listConnectedDevices();

/// Whether a HID vendor and product is a 3Dconnexion SpaceMouse.
bool isSpaceMouse(std::uint16_t vendorId, std::uint16_t productId);

} // namespace proxima
