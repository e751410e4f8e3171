// The shared secret of `proxima serve` and `proxima remote` (--token-file): the file's first line,
// without surrounding blanks.
#pragma once

#include "IO/InputChecks/InputError.h"

#include <fstream>
#include <string>

namespace proxima::cli
{

/// Throws InputError naming the file when it cannot be read or holds no token.
inline std::string readTokenFile(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line))
  {
    throw InputError(path, "cannot read the token file");
  }
  const auto first = line.find_first_not_of(" \t\r");
  const auto last = line.find_last_not_of(" \t\r");
  if (first == std::string::npos)
  {
    throw InputError(path, "the token file's first line is empty: write the token there");
  }
  return line.substr(first, last - first + 1);
}

} // namespace proxima::cli
