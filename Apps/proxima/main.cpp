// proxima: the front of the command line. It lists the subcommands (`proxima --help`) and words
// the refusal of a command line without a known one itself; every other command line goes, as
// given, to the subcommand's own program proxima-<command> beside it (CommandProgram.cpp), as
// git hands `git <command>` on. The front links no library of the toolkit, so it starts in a few
// milliseconds, and each subcommand's program loads only what that subcommand uses (VTK's
// rendering only for view): a suite of hundreds of `proxima run`s does not pay the viewer's start.
#include "Command.h"
#include "CommandSummaries.h"
#include "ProximaApp.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
using namespace proxima::cli;

/// The folder of this program, with a trailing slash: the subcommands' programs are beside it,
/// wherever the build or an installation put them and whatever the PATH says.
std::string programFolder()
{
  std::string buffer(PATH_MAX, '\0');
  const ssize_t length = readlink("/proc/self/exe", buffer.data(), buffer.size());
  if (length <= 0)
  {
    return {};
  }
  buffer.resize(static_cast<std::size_t>(length));
  return buffer.substr(0, buffer.rfind('/') + 1);
}

/// Replaces this process by the program of subcommand `name`, given the whole command line (the
/// program parses it as the one `proxima` did before the split). Returns only on failure.
int handOn(const char* name, char** argv)
{
  const std::string program = programFolder() + "proxima-" + name;
  execv(program.c_str(), argv);
  std::cerr << "proxima: internal error: cannot run " << program << ": " << std::strerror(errno)
            << "\n";
  return kExitInternalError;
}
} // namespace

int main(int argc, char** argv)
{
  // A command line naming a subcommand goes to its program without being parsed here, wherever
  // the name is (`proxima run ...`, and `proxima --help run`, which shows run's help): the
  // program parses the whole line as the one `proxima` did before the split.
  for (int i = 1; i < argc; ++i)
  {
    for (const CommandSummary& summary : kCommandSummaries)
    {
      if (std::strcmp(argv[i], summary.name) == 0)
      {
        return handOn(summary.name, argv);
      }
    }
  }

  // Everything else (--help, no subcommand, an unknown one) is parsed against the subcommands'
  // names and descriptions, which is all that `proxima --help` and its errors show of them.
  CLI::App app{kProximaDescription, "proxima"};
  configureProximaApp(app);
  for (const CommandSummary& summary : kCommandSummaries)
  {
    app.add_subcommand(summary.name, summary.description);
  }
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
    // Help sent to a full disk or /dev/full is lost, not shown: not a success either. The front
    // links no library, so the check of IO/Output/StandardOutput.cpp is made here by hand, in its
    // words.
    const std::string text = help.str();
    errno = 0;
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
    {
      const int lost = errno;
      std::cerr << "proxima: cannot write to standard output: "
                << (lost != 0 ? std::strerror(lost) : "a short write") << "\n";
      return kExitBadInput;
    }
    return kExitOk;
  }
  // Not reached: without a subcommand's name, require_subcommand fails the parse.
  std::cerr << "proxima: no subcommand given (see proxima --help)\n";
  return kExitBadInput;
}
