// The exception every writer of Proxima throws when an output cannot be written in full: a
// missing folder, a full disk, a file-size limit, an output that would overwrite one of the
// run's inputs. It is an InputError, so that every command line already prints its what() as
// one line and exits with status 2: the user named a file that cannot take the output.
#pragma once

#include "IO/InputChecks/InputError.h"

#include <string>

namespace proxima
{

/// An output that cannot be written in full, or is refused before it is written; made by
/// cannotWrite(), refused() or standardOutput(), its what() one line like any InputError's.
class OutputError : public InputError
{
public:
  /// "<path>: cannot write the file (<reason>)", reason being the system's word for the failure
  /// (strerror: "No space left on device", "File too large").
  static OutputError cannotWrite(const std::string& path, const std::string& reason)
  {
    return OutputError(path, "cannot write the file (" + reason + ")");
  }

  /// "<path>: <refusal>", for an output refused before anything is written (it is an input).
  static OutputError refused(const std::string& path, const std::string& refusal)
  {
    return OutputError(path, refusal);
  }

  /// "cannot write to standard output: <reason>".
  static OutputError standardOutput(const std::string& reason)
  {
    return OutputError("cannot write to standard output", reason);
  }

private:
  OutputError(const std::string& path, const std::string& defect)
    : InputError(path, defect)
  {}
};

} // namespace proxima
