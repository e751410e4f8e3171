// One subcommand of the `proxima` program. A subcommand lives in its own file and provides an
// add function that registers its options on the parent CLI11 app and returns what to run once
// the command line is parsed; it runs in its own program, proxima-<command>, which the front
// (main.cpp) hands the command line to. To add one (say `bench`): write BenchCommand.cpp defining
// addBenchCommand, declare it in CommandProgram.h, give it a summary in CommandSummaries.h (kCommandSummaries
// is what the front knows of it) and a proxima_add_command line in CMakeLists.txt.
#pragma once

#include "CommandProgram.h"
#include "CommandSummaries.h"

#include <CLI/CLI.hpp>

#include <functional>

namespace proxima::cli
{

/// Exit statuses shared by every subcommand (DESIGN.md section 3).
enum ExitStatus : int
{
  kExitOk = 0,
  kExitInternalError = 1,
  kExitBadInput = 2
};

struct Command
{
  /// The subcommand's CLI11 node, owned by the parent app.
  CLI::App* app = nullptr;
  /// Runs the command after parsing and returns the exit status. Throws InputError for bad
  /// input (main prints it and exits with 2); any other exception is an internal error (1).
  std::function<int()> run;
};

} // namespace proxima::cli
