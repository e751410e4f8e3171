// What the applications' programs (proxima-trainer, proxima-inspector) share around their own
// work: the window's device options, and the exit statuses of DESIGN.md section 3 (0 when the
// work ran, 2 for bad input or an output that cannot be written, in one line naming the file and
// the defect, 1 for an internal error; --help lost on a full disk is not a success). Header only:
// CLI11 is too.
#pragma once

#include "UsageErrors.h"

#include "Devices/DeviceRegistry.h"
#include "IO/InputChecks/InputError.h"
#include "IO/Output/StandardOutput.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <functional>
#include <iostream>
#include <string>

namespace proxima::shell
{

/// --device (the window's: mouse, spacemouse, falcon or replay:FILE) and --falcon-firmware.
inline void addWindowDeviceOptions(CLI::App& app, std::string& device, std::string& falconFirmware)
{
  app
    .add_option("--device", device,
                "The window's device: mouse (default), spacemouse, falcon or replay:FILE")
    ->check(CLI::Validator(
      [](std::string& input) -> std::string {
        return isDeviceSpec(input) && input != "sim"
                 ? std::string()
                 : "must be mouse, spacemouse, falcon or replay:FILE, not " + input;
      },
      "DEVICE"));
  app.add_option("--falcon-firmware", falconFirmware,
                 "With --device falcon: the firmware file to upload (your own copy)");
}

/// Parses the command line into `app`'s options and runs `work`, which returns the exit status;
/// errors become one line on standard error that begins with `program`.
inline int runProgram(CLI::App& app, const std::string& program, int argc, char** argv,
                      const std::function<int()>& work)
{
  // A file-size limit fails a write with EFBIG, reported like a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  // A usage error in one line, as bad input is (not CLI11's two, the second "Run with --help"),
  // an unknown option named with the nearest valid one, as for proxima (UsageErrors.h).
  cli::configureUsageErrors(app, program);
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& error)
  {
    if (app.exit(error) != 0)
    {
      return 2;
    }
    try
    {
      finishStandardOutput();
    }
    catch (const InputError& lost)
    {
      std::cerr << program << ": " << lost.what() << "\n";
      return 2;
    }
    return 0;
  }
  try
  {
    return work();
  }
  catch (const InputError& error)
  {
    std::cerr << program << ": " << error.what() << "\n";
    return 2;
  }
  catch (const std::exception& error)
  {
    std::cerr << program << ": internal error: " << error.what() << "\n";
    return 1;
  }
}

} // namespace proxima::shell
