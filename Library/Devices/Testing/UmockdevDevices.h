// The emulators behind real device nodes, through umockdev: a testbed (fake /sys and /dev in
// user space, by the preload library the test is linked with) holding a hidraw node whose reads,
// writes and ioctls reach a SpaceMouseEmulator, and a usbfs node whose URBs reach a
// FalconEmulator behind an FTDI bridge. hidapi and libusb then run their real Linux code paths
// against them. The umockdev headers stay in the .cpp file.
#pragma once

#include "FalconEmulator.h"
#include "SpaceMouseEmulator.h"

#include <memory>
#include <string>

namespace proxima::testing
{

class UmockdevBed
{
public:
  UmockdevBed();
  ~UmockdevBed();
  UmockdevBed(const UmockdevBed&) = delete;
  UmockdevBed& operator=(const UmockdevBed&) = delete;

  /// Adds a USB HID device with a hidraw node (/dev/hidraw0) served by `emulator`.
  void addHidraw(SpaceMouseEmulator& emulator, std::uint16_t vendorId, std::uint16_t productId,
                 const std::string& product);
  /// Adds a USB device 0403:cb48 (/dev/bus/usb/001/002) served by `emulator`.
  void addFalcon(FalconEmulator& emulator);
  /// Unplugs: the device's node answers ENODEV/EIO from now on, and it leaves sysfs.
  void unplugHidraw();
  void unplugFalcon();

  /// True when the testbed's /sys is what this process sees (the preload library is active).
  bool active() const;

  struct Impl;

private:
  std::unique_ptr<Impl> m_impl;
};

} // namespace proxima::testing
