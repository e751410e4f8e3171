// proxima-<command>: the program of one subcommand, which the `proxima` front (main.cpp) runs
// with the command line it was given. Parses it, runs the subcommand and maps failures to the
// exit statuses of DESIGN.md section 3: 0 success, 2 bad input or an output that cannot be
// written (one line on stderr naming the file and the defect), 1 internal error. Built once per subcommand, PROXIMA_ADD_COMMAND naming
// its add function (Apps/proxima/CMakeLists.txt), so that each program links only the libraries
// its subcommand uses: `proxima run` on an OBJ file does not load VTK's rendering.
#include "Command.h"
#include "ProximaApp.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Output/StandardOutput.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <iostream>

#ifndef PROXIMA_ADD_COMMAND
#error "PROXIMA_ADD_COMMAND must name the add function of the subcommand this program runs"
#endif

int main(int argc, char** argv)
{
  // A file-size limit (ulimit -f) then fails a write with EFBIG, which the writers report like a
  // full disk (status 2, the file named), instead of killing the program mid-write.
  std::signal(SIGXFSZ, SIG_IGN);

  CLI::App app{proxima::cli::kProximaDescription, "proxima"};
  proxima::cli::configureProximaApp(app);

  const proxima::cli::Command command = proxima::cli::PROXIMA_ADD_COMMAND(app);

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
    if (command.app->parsed())
    {
      const int status = command.run();
      // A report lost on the way to standard output (a full disk, /dev/full) is not a success.
      proxima::finishStandardOutput();
      return status;
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
