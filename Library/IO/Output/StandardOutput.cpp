#include "IO/Output/StandardOutput.h"

#include "IO/Output/OutputError.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace proxima
{
namespace
{
/// Flushes std::cout and stdout, throwing with the system's reason when that fails.
void flushBoth()
{
  errno = 0;
  std::cout.flush();
  const int coutError = errno;
  if (std::fflush(stdout) != 0)
  {
    throw OutputError::standardOutput(std::strerror(errno));
  }
  if (!std::cout || std::ferror(stdout) != 0)
  {
    // stdio drops a buffer it failed to write and remembers only that it failed.
    throw OutputError::standardOutput(coutError != 0 ? std::strerror(coutError)
                                                     : "an earlier write failed");
  }
}
} // namespace

void writeStandardOutput(std::string_view text)
{
  flushBoth();
  errno = 0;
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size())
  {
    const int error = errno;
    throw OutputError::standardOutput(error != 0 ? std::strerror(error) : "a short write");
  }
  flushBoth();
}

void finishStandardOutput()
{
  flushBoth();
}

} // namespace proxima
