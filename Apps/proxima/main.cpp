// proxima: the command line of the toolkit. Parses the command line, runs the one subcommand
// given and maps failures to the exit statuses of DESIGN.md section 3: 0 success, 2 bad input
// (one line on stderr naming the file and the defect), 1 internal error.
#include "Command.h"

#include "IO/InputChecks/InputError.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <vector>

namespace
{
using proxima::cli::Command;

// Every subcommand, in the order `proxima --help` lists them.
constexpr Command (*kCommands[])(CLI::App&) = {
  proxima::cli::addRunCommand,
  proxima::cli::addViewCommand,
  proxima::cli::addPathCommand,
  proxima::cli::addTreeCommand,
  proxima::cli::addGenerateCommand,
  proxima::cli::addDevicesCommand,
};
} // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Proxima: haptic rendering with the virtual-proxy method of Ruspini and Khatib.",
               "proxima"};
  app.require_subcommand(1);
  // Usage errors get one line too, in the same shape as bad input.
  app.failure_message([](const CLI::App*, const CLI::Error& error) {
    return std::string("proxima: ") + error.what() + " (see proxima --help)\n";
  });

  std::vector<Command> commands;
  for (auto add : kCommands)
  {
    commands.push_back(add(app));
  }

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& error)
  {
    // --help and --version are "errors" with status 0; every real usage error is bad input.
    const int status = app.exit(error);
    return status == 0 ? proxima::cli::kExitOk : proxima::cli::kExitBadInput;
  }

  try
  {
    for (const Command& command : commands)
    {
      if (command.app->parsed())
      {
        return command.run();
      }
    }
    std::cerr << "proxima: no subcommand given (see proxima --help)\n";
    return proxima::cli::kExitBadInput;
  }
  catch (const proxima::InputError& error)
  {
    std::cerr << "proxima: " << error.what() << "\n";
    return proxima::cli::kExitBadInput;
  }
  catch (const std::exception& error)
  {
    std::cerr << "proxima: internal error: " << error.what() << "\n";
    return proxima::cli::kExitInternalError;
  }
  catch (...)
  {
    std::cerr << "proxima: internal error of unknown kind\n";
    return proxima::cli::kExitInternalError;
  }
}
