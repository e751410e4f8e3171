// The main of every proxima-<command> program: each is built from a generated main that hands its
// subcommand's add function (Command.h) to runCommandProgram (Apps/proxima/CMakeLists.txt), so
// that each program links only the libraries its subcommand uses while the parsing and the exit
// statuses are compiled once. Light on purpose: the generated mains include nothing else.
#pragma once

namespace CLI
{
class App;
}

namespace proxima::cli
{

struct Command;

Command addRunCommand(CLI::App& parent);
Command addViewCommand(CLI::App& parent);
Command addPathCommand(CLI::App& parent);
Command addTreeCommand(CLI::App& parent);
/// `proxima tissue`: an organ surface wrapped and filled with tetrahedra (TissueCommand.cpp).
Command addTissueCommand(CLI::App& parent);
Command addInspectCommand(CLI::App& parent);
Command addGenerateCommand(CLI::App& parent);
Command addDevicesCommand(CLI::App& parent);
Command addServeCommand(CLI::App& parent);
Command addRemoteCommand(CLI::App& parent);

using AddCommandFunction = Command (*)(CLI::App& parent);

/// Parses the command line with the subcommand `addCommand` registers, runs it and maps failures
/// to the exit statuses of DESIGN.md section 3: 0 success, 2 bad input or an output that cannot
/// be written (one line on stderr naming the file and the defect), 1 internal error.
int runCommandProgram(int argc, char** argv, AddCommandFunction addCommand);

} // namespace proxima::cli
