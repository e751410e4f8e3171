// Runs code as if the disk were full: in a child process whose files may not grow past a limit
// (RLIMIT_FSIZE), with SIGXFSZ ignored as the command line ignores it, so that writes past the
// limit fail with EFBIG. For the tests of outputs that must fail cleanly (DESIGN.md section 6).
#pragma once

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <exception>
#include <functional>
#include <string>

namespace proxima::testing_support
{

/// Runs `body` in a child whose files may not grow past `limitBytes` and returns the what() of
/// the exception it threw ("" when it threw none).
inline std::string messageUnderFileSizeLimit(rlim_t limitBytes, const std::function<void()>& body)
{
  int channel[2];
  if (::pipe(channel) != 0)
  {
    return "pipe failed";
  }
  const pid_t child = ::fork();
  if (child == 0)
  {
    ::close(channel[0]);
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{limitBytes, limitBytes};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    std::string message;
    try
    {
      body();
    }
    catch (const std::exception& error)
    {
      message = error.what();
    }
    (void)!::write(channel[1], message.data(), message.size());
    ::_exit(0);
  }
  ::close(channel[1]);
  std::string message;
  char chunk[256];
  ssize_t n = 0;
  while ((n = ::read(channel[0], chunk, sizeof chunk)) > 0)
  {
    message.append(chunk, static_cast<std::size_t>(n));
  }
  ::close(channel[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status)) << "the child died of signal " << WTERMSIG(status);
  return message;
}

} // namespace proxima::testing_support
