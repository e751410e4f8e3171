// The one exception the IO layer throws when a file the user named cannot be used (missing,
// unreadable, garbled, or holding bad numbers): what() is a single line "<path>: <defect>", ready
// for a command line to print as is and exit with status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace proxima
{

/// A file or value the user gave that cannot be used; what() is "<path>: <defect>" on one line.
class InputError : public std::runtime_error
{
public:
  /// An error about `path` (a file, or an option such as "--max-ticks"); `defect` says what is
  /// wrong, and its line breaks and runs of white space become single spaces.
  InputError(const std::string& path, const std::string& defect)
    : std::runtime_error(path + ": " + oneLine(defect))
    , m_path(path)
    , m_defect(oneLine(defect))
  {}

  /// The file as the caller named it.
  const std::string& path() const { return m_path; }
  /// What is wrong with it, without the path.
  const std::string& defect() const { return m_defect; }

private:
  // Third-party readers word their complaints over several lines; a caller prints one line.
  static std::string oneLine(const std::string& text)
  {
    std::string line;
    line.reserve(text.size());
    bool pendingSpace = false;
    for (char c : text)
    {
      if (c == '\n' || c == '\r' || c == '\t' || c == ' ')
      {
        pendingSpace = !line.empty();
        continue;
      }
      if (pendingSpace)
      {
        line.push_back(' ');
        pendingSpace = false;
      }
      line.push_back(c);
    }
    return line;
  }

  std::string m_path;
  std::string m_defect;
};

} // namespace proxima
