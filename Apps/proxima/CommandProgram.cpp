// proxima-<command>: the program of one subcommand, which the `proxima` front (main.cpp) runs
// with the command line it was given (CommandProgram.h). Each program links only the libraries
// its subcommand uses: `proxima run` on an OBJ file does not load VTK's rendering.
#include "CommandProgram.h"

#include "Command.h"
#include "ProximaApp.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Output/StandardOutput.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <iostream>
#include <sstream>

namespace proxima::cli
{

int runCommandProgram(int argc, char** argv, AddCommandFunction addCommand)
{
  // A file-size limit (ulimit -f) then fails a write with EFBIG, which the writers report like a
  // full disk (status 2, the file named), instead of killing the program mid-write.
  std::signal(SIGXFSZ, SIG_IGN);

  CLI::App app{kProximaDescription, "proxima"};
  configureProximaApp(app);

  const Command command = addCommand(app);

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& error)
  {
    // --help and --version are "errors" with status 0; every real usage error is bad input (its
    // message goes to standard error). The help is made in memory and written in one piece, so
    // that a failed write is seen with its reason however long the text.
    std::ostringstream help;
    const int status = app.exit(error, help, std::cerr);
    if (status != 0)
    {
      return kExitBadInput;
    }
    try
    {
      // Help sent to a full disk or /dev/full is lost, not shown: not a success either.
      writeStandardOutput(help.str());
      finishStandardOutput();
    }
    catch (const InputError& lost)
    {
      std::cerr << "proxima: " << lost.what() << "\n";
      return kExitBadInput;
    }
    return kExitOk;
  }

  try
  {
    if (command.app->parsed())
    {
      const int status = command.run();
      // A report lost on the way to standard output (a full disk, /dev/full) is not a success.
      proxima::finishStandardOutput();
      return status;
    }
    std::cerr << "proxima: no subcommand given (see proxima --help)\n";
    return kExitBadInput;
  }
  catch (const proxima::InputError& error)
  {
    std::cerr << "proxima: " << error.what() << "\n";
    return kExitBadInput;
  }
  catch (const std::exception& error)
  {
    std::cerr << "proxima: internal error: " << error.what() << "\n";
    return kExitInternalError;
  }
  catch (...)
  {
    std::cerr << "proxima: internal error of unknown kind\n";
    return kExitInternalError;
  }
}

} // namespace proxima::cli
