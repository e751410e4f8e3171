#include "IO/Output/OutputIdentity.h"

#include "IO/Output/OutputError.h"

#include <sys/stat.h>

#include <filesystem>
#include <system_error>

namespace proxima
{
namespace
{
namespace fs = std::filesystem;

fs::path normalPath(const std::string& path)
{
  std::error_code error;
  fs::path normal = fs::weakly_canonical(fs::absolute(path, error), error);
  return error ? fs::path(path).lexically_normal() : normal;
}
} // namespace

bool namesSameFile(const std::string& a, const std::string& b)
{
  if (a.empty() || b.empty())
  {
    return false;
  }
  struct stat first
  {};
  struct stat second
  {};
  const bool firstExists = ::stat(a.c_str(), &first) == 0;
  const bool secondExists = ::stat(b.c_str(), &second) == 0;
  if ((firstExists && !S_ISREG(first.st_mode)) || (secondExists && !S_ISREG(second.st_mode)))
  {
    return false;
  }
  if (firstExists && secondExists)
  {
    return first.st_dev == second.st_dev && first.st_ino == second.st_ino;
  }
  if (firstExists != secondExists)
  {
    return false;
  }
  return normalPath(a) == normalPath(b);
}

void refuseOverlappingFiles(const std::vector<NamedFile>& outputs,
                            const std::vector<NamedFile>& inputs)
{
  for (std::size_t i = 0; i < outputs.size(); ++i)
  {
    const NamedFile& output = outputs[i];
    for (const NamedFile& input : inputs)
    {
      if (namesSameFile(output.path, input.path))
      {
        throw OutputError::refused(output.path, output.role + " is the same file as " + input.role +
                                                  ", which it would overwrite");
      }
    }
    for (std::size_t j = 0; j < i; ++j)
    {
      if (namesSameFile(output.path, outputs[j].path))
      {
        throw OutputError::refused(output.path, output.role + " and " + outputs[j].role +
                                                  " name the same file; give each its own");
      }
    }
  }
}

} // namespace proxima
