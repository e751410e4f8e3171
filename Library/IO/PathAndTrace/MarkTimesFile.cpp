#include "IO/PathAndTrace/MarkTimesFile.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/InputChecks/InputError.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>

namespace proxima
{
namespace
{
std::string trimmed(const std::string& text)
{
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
  {
    return {};
  }
  const std::size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}
} // namespace

std::vector<double> readMarkTimesFile(const std::string& path)
{
  detail::requireReadableFile(path, "marks file");
  std::ifstream stream(path);
  if (!stream)
  {
    throw InputError(path, std::string("cannot open the file (") + std::strerror(errno) + ")");
  }
  std::vector<double> times;
  std::string line;
  std::size_t number = 0;
  bool header = false;
  while (std::getline(stream, line))
  {
    ++number;
    const std::string text = trimmed(line);
    if (text.empty())
    {
      continue;
    }
    const std::string where = "line " + std::to_string(number) + ": ";
    if (!header)
    {
      if (text != "t")
      {
        throw InputError(path, where + "the header must be `t` (one mark time per row), got `" +
                                 text.substr(0, 40) + "`");
      }
      header = true;
      continue;
    }
    double time = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), time);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(time))
    {
      throw InputError(path, where + "a mark time must be one finite number of seconds, got `" +
                               text.substr(0, 40) + "`");
    }
    if (!times.empty() && time < times.back())
    {
      throw InputError(path, where + "the marks go back in time (" + text + " s after " +
                               std::to_string(times.back()) + " s)");
    }
    times.push_back(time);
  }
  if (stream.bad())
  {
    throw InputError(path, "cannot read the file");
  }
  if (!header)
  {
    throw InputError(path, "the file is empty (it needs the header `t`)");
  }
  return times;
}

} // namespace proxima
