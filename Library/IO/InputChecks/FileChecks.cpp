#include "IO/InputChecks/FileChecks.h"

#include "IO/InputChecks/InputError.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace proxima::detail
{

std::uintmax_t requireReadableFile(const std::string& path, const std::string& kind)
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error || !fs::exists(status))
  {
    throw InputError(path, "cannot open the file (" +
                             (error ? error.message() : std::string("No such file or directory")) +
                             ")");
  }
  if (fs::is_directory(status))
  {
    throw InputError(path, "is a directory, not a " + kind);
  }
  if (!fs::is_regular_file(status))
  {
    throw InputError(path, "is not a regular file");
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream)
  {
    throw InputError(path, std::string("cannot open the file (") + std::strerror(errno) + ")");
  }
  const std::uintmax_t size = fs::file_size(path, error);
  if (error)
  {
    throw InputError(path, "cannot read the file size (" + error.message() + ")");
  }
  if (size == 0)
  {
    throw InputError(path, "the file is empty");
  }
  return size;
}

std::string readWholeFile(const std::string& path, const std::string& kind)
{
  requireReadableFile(path, kind);
  std::ifstream stream(path, std::ios::binary);
  if (!stream)
  {
    throw InputError(path, std::string("cannot open the file (") + std::strerror(errno) + ")");
  }
  std::string text{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (stream.bad())
  {
    throw InputError(path, "cannot read the file");
  }
  if (text.empty())
  {
    throw InputError(path, "the file is empty");
  }
  return text;
}

std::string readFileHead(const std::string& path, std::size_t count)
{
  std::ifstream stream(path, std::ios::binary);
  std::string head(count, '\0');
  stream.read(head.data(), static_cast<std::streamsize>(count));
  head.resize(static_cast<std::size_t>(stream.gcount()));
  return head;
}

std::string trimmedHead(const std::string& head)
{
  std::size_t start = head.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  while (start < head.size() &&
         (head[start] == ' ' || head[start] == '\t' || head[start] == '\r' || head[start] == '\n'))
  {
    ++start;
  }
  return head.substr(start);
}

} // namespace proxima::detail
