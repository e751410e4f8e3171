// `proxima devices`: the haptic devices connected now, by the --device name that opens them
// (SpaceMice over hidraw, Falcons over USB), and the two that always exist.
#include "Command.h"

#include "Devices/DeviceRegistry.h"

#include <iostream>

namespace proxima::cli
{

Command addDevicesCommand(CLI::App& parent)
{
  CLI::App* app = parent.add_subcommand(kDevicesSummary.name, kDevicesSummary.description);
  return Command{app, [] {
                   const auto devices = listConnectedDevices();
                   for (const ConnectedDevice& device : devices)
                   {
                     std::cout << device.name << "\t" << device.description << "\n";
                   }
                   if (devices.empty())
                   {
                     std::cout << "no SpaceMouse or Falcon connected (or none readable: see the "
                                  "udev rules in Documentation/Devices.md)\n";
                   }
                   std::cout << "sim\tthe scripted finger path of --path (always)\n"
                             << "replay:FILE\ta recording made with --record-device (always)\n";
                   return kExitOk;
                 }};
}

} // namespace proxima::cli
