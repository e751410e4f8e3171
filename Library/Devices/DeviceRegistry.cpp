#include "Devices/DeviceRegistry.h"

#include "Devices/FalconDevice.h"
#include "Devices/HidapiTransport.h"
#include "Devices/LibusbTransport.h"
#include "Devices/ReplayDevice.h"
#include "Devices/SpaceMouseDevice.h"
#include "Runtime/PointerDevice.h"
#include "Runtime/SimulatedDevice.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace proxima
{
namespace
{
constexpr std::uint16_t kFalconVendor = 0x0403;
constexpr std::uint16_t kFalconProduct = 0xcb48;
// 3Dconnexion devices sold under Logitech's vendor ID (SpaceNavigator, SpaceExplorer,
// SpacePilot, SpaceMouse Pro, Wireless, ...); every device under 3Dconnexion's own ID is one.
constexpr std::uint16_t kLogitechSpaceMice[] = {0xc603, 0xc605, 0xc606, 0xc621, 0xc623,
                                                0xc625, 0xc626, 0xc627, 0xc628, 0xc629,
                                                0xc62b, 0xc62e, 0xc62f};

std::string hexIds(std::uint16_t vendor, std::uint16_t product)
{
  char text[16];
  std::snprintf(text, sizeof text, "%04x:%04x", vendor, product);
  return text;
}

std::unique_ptr<HapticDevice> openSpaceMouse(const DeviceOptions& options, std::string& error)
{
  for (const HidDeviceInfo& info : enumerateHidDevices())
  {
    if (!isSpaceMouse(info.vendorId, info.productId))
    {
      continue;
    }
    SpaceMouseSettings settings;
    settings.centre = options.path.empty() ? Vec3{} : options.path.positions.front();
    std::string descriptorError;
    const auto descriptor = readHidReportDescriptor(info.path, descriptorError);
    std::optional<SpaceMouseLayout> layout;
    if (descriptor)
    {
      layout = spaceMouseLayoutFromDescriptor(*descriptor, descriptorError);
    }
    // Without a readable descriptor, the vendor tells the generation.
    settings.layout = layout.value_or(info.vendorId == kSpaceMouseVendor3Dconnexion
                                        ? SpaceMouseLayout::SixAxisReport
                                        : SpaceMouseLayout::SplitReports);
    auto transport = openHidapiTransport(info.path, error);
    if (!transport)
    {
      return nullptr;
    }
    auto device = std::make_unique<SpaceMouseDevice>(std::move(transport), settings);
    device->setLed(true);
    return device;
  }
  error = "spacemouse: no 3Dconnexion device (vendor 046d or 256f) is connected, or none is "
          "readable (see the udev rule in Documentation/Devices.md)";
  return nullptr;
}

std::unique_ptr<HapticDevice> openFalcon(const DeviceOptions& options, std::string& error)
{
  FalconSettings settings;
  settings.firmwarePath = options.falconFirmware;
  settings.worldOffset = options.path.empty() ? Vec3{} : options.path.positions.front();
  if (settings.firmwarePath.empty())
  {
    error = "falcon: the Falcon needs its firmware, which Proxima does not ship: give your own "
            "copy with --falcon-firmware FILE (Documentation/Devices.md)";
    return nullptr;
  }
  // The file first: a missing firmware is the user's to fix before any device is touched.
  if (!std::ifstream(settings.firmwarePath, std::ios::binary))
  {
    error = settings.firmwarePath +
            ": cannot open the Falcon firmware file; Proxima does not ship it: give your own copy "
            "with --falcon-firmware (Documentation/Devices.md)";
    return nullptr;
  }
  auto transport = openFtdiTransport(kFalconVendor, kFalconProduct, error);
  if (!transport)
  {
    error = "falcon: " + error;
    return nullptr;
  }
  auto device = std::make_unique<FalconDevice>(std::move(transport), settings);
  if (!device->open(error))
  {
    return nullptr;
  }
  return device;
}
} // namespace

const char* const kDeviceNames = "sim, replay:FILE, mouse, spacemouse, falcon";

bool isSpaceMouse(std::uint16_t vendorId, std::uint16_t productId)
{
  if (vendorId == kSpaceMouseVendor3Dconnexion)
  {
    return true;
  }
  return vendorId == kSpaceMouseVendorLogitech &&
         std::find(std::begin(kLogitechSpaceMice), std::end(kLogitechSpaceMice), productId) !=
           std::end(kLogitechSpaceMice);
}

bool isDeviceSpec(const std::string& spec)
{
  return spec == "sim" || spec == "mouse" || spec == "spacemouse" || spec == "falcon" ||
         (spec.rfind("replay:", 0) == 0 && spec.size() > 7);
}

std::unique_ptr<HapticDevice> openDevice(const std::string& spec, const DeviceOptions& options,
                                         std::string& error)
{
  if (spec == "sim")
  {
    if (options.path.empty())
    {
      error = "sim: the simulated device needs a finger path";
      return nullptr;
    }
    return std::make_unique<SimulatedDevice>(options.path);
  }
  if (spec.rfind("replay:", 0) == 0 && spec.size() > 7)
  {
    auto samples = readDeviceRecording(spec.substr(7), error);
    if (!samples)
    {
      return nullptr;
    }
    return std::make_unique<ReplayDevice>(std::move(*samples));
  }
  if (spec == "mouse")
  {
    // The window that owns the pointer aims it (proxima view); it starts where the path does.
    PointerDeviceSettings settings;
    settings.start = options.path.empty() ? Vec3{} : options.path.positions.front();
    return std::make_unique<PointerDevice>(settings);
  }
  if (spec == "spacemouse")
  {
    return openSpaceMouse(options, error);
  }
  if (spec == "falcon")
  {
    return openFalcon(options, error);
  }
  error = spec + ": not a device (use one of " + kDeviceNames + ")";
  return nullptr;
}

std::vector<ConnectedDevice> listConnectedDevices()
{
  std::vector<ConnectedDevice> devices;
  for (const HidDeviceInfo& info : enumerateHidDevices())
  {
    if (isSpaceMouse(info.vendorId, info.productId))
    {
      devices.push_back({"spacemouse", hexIds(info.vendorId, info.productId) + " " +
                                         info.manufacturer + " " + info.product + " at " +
                                         info.path});
    }
  }
  for (const UsbDeviceInfo& info : enumerateUsbDevices(kFalconVendor, kFalconProduct))
  {
    char where[48];
    std::snprintf(where, sizeof where, " on USB bus %d address %d", info.bus, info.address);
    devices.push_back({"falcon", hexIds(info.vendorId, info.productId) + " Novint Falcon" + where});
  }
  return devices;
}

} // namespace proxima
