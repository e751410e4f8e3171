// What the `proxima` front and every subcommand's program share at the top of the command line:
// the program's name and description and how usage errors are worded, so that a command line
// reads the same whichever of them parses it.
#pragma once

#include "UsageErrors.h"

#include <CLI/CLI.hpp>

#include <string>

namespace proxima::cli
{

inline constexpr const char* kProximaDescription =
  "Proxima: haptic rendering with the virtual-proxy method of Ruspini and Khatib.";

/// Requires one subcommand, and words usage errors in one line, in the same shape as bad input
/// (UsageErrors.h: an unknown word is named with the nearest valid one).
inline void configureProximaApp(CLI::App& app)
{
  app.require_subcommand(1);
  configureUsageErrors(app, "proxima");
}

} // namespace proxima::cli
