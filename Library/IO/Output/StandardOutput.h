// Reports on standard output whose loss is an error, not a silent success: a JSON report piped
// to a full disk or to /dev/full must fail the command (status 2), as a file would.
#pragma once

#include <string_view>

namespace proxima
{

/// Writes `text` to standard output and flushes it. Throws OutputError ("cannot write to
/// standard output: <reason>") when the system refuses it.
void writeStandardOutput(std::string_view text);

/// Flushes standard output (std::cout and stdio alike) and throws OutputError if anything
/// written to it, now or before, was lost: a program's last check before it exits with 0.
void finishStandardOutput();

} // namespace proxima
