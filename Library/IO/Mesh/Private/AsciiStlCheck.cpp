#include "IO/Mesh/Private/AsciiStlCheck.h"

#include "IO/InputChecks/InputError.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <strings.h>

namespace proxima::detail
{
namespace
{
/// Whitespace-separated words of the file with their line numbers, lines bounded in length.
class WordStream
{
public:
  explicit WordStream(const std::string& path)
    : m_path(path)
    , m_stream(path, std::ios::binary)
  {}

  /// The next word, or an empty string at the end of the file.
  std::string next()
  {
    while (true)
    {
      while (m_position < m_line.size() &&
             std::isspace(static_cast<unsigned char>(m_line[m_position])))
      {
        ++m_position;
      }
      if (m_position < m_line.size())
      {
        const std::size_t start = m_position;
        while (m_position < m_line.size() &&
               !std::isspace(static_cast<unsigned char>(m_line[m_position])))
        {
          ++m_position;
        }
        return m_line.substr(start, m_position - start);
      }
      if (!readLine())
      {
        return {};
      }
    }
  }

  /// Drops the rest of the current line (a solid's name).
  void skipLine() { m_position = m_line.size(); }

  std::size_t lineNumber() const { return m_lineNumber; }

  [[noreturn]] void fail(const std::string& defect) const
  {
    throw InputError(m_path, "not a valid ASCII STL file: line " + std::to_string(m_lineNumber) +
                               ": " + defect);
  }

private:
  bool readLine()
  {
    m_line.clear();
    m_position = 0;
    char c = 0;
    bool any = false;
    while (m_stream.get(c))
    {
      any = true;
      if (c == '\n')
      {
        break;
      }
      if (m_line.size() == kMaxAsciiStlLine)
      {
        ++m_lineNumber;
        fail("longer than " + std::to_string(kMaxAsciiStlLine) + " bytes");
      }
      m_line.push_back(c);
    }
    if (any)
    {
      ++m_lineNumber;
    }
    return any;
  }

  const std::string& m_path;
  std::ifstream m_stream;
  std::string m_line;
  std::size_t m_position = 0;
  std::size_t m_lineNumber = 0;
};

bool is(const std::string& word, const char* keyword)
{
  return strcasecmp(word.c_str(), keyword) == 0;
}

std::string shown(const std::string& word)
{
  if (word.empty())
  {
    return "the end of the file";
  }
  std::string text;
  for (char c : word.substr(0, 32))
  {
    const auto byte = static_cast<unsigned char>(c);
    text += byte >= 0x20 && byte < 0x7f ? c : '?';
  }
  return "'" + text + (word.size() > 32 ? "...'" : "'");
}

void expect(WordStream& words, const char* keyword)
{
  const std::string word = words.next();
  if (!is(word, keyword))
  {
    words.fail(std::string("expected '") + keyword + "', found " + shown(word));
  }
}

void expectNumbers(WordStream& words, const char* what)
{
  for (int i = 0; i < 3; ++i)
  {
    const std::string word = words.next();
    char* end = nullptr;
    (void)std::strtod(word.c_str(), &end);
    if (word.empty() || end != word.c_str() + word.size())
    {
      words.fail(std::string("expected three numbers after '") + what + "', found " + shown(word));
    }
  }
}
} // namespace

void checkAsciiStl(const std::string& path)
{
  WordStream words(path);
  std::size_t facets = 0;
  std::string word = words.next();
  if (!is(word, "solid"))
  {
    words.fail("expected 'solid', found " + shown(word));
  }
  words.skipLine();
  while (true)
  {
    word = words.next();
    if (is(word, "endsolid"))
    {
      words.skipLine();
      word = words.next();
      if (word.empty())
      {
        break;
      }
      if (!is(word, "solid"))
      {
        words.fail("expected 'solid' or the end of the file after 'endsolid', found " +
                   shown(word));
      }
      words.skipLine();
      continue;
    }
    if (!is(word, "facet"))
    {
      words.fail("expected 'facet' or 'endsolid', found " + shown(word));
    }
    expect(words, "normal");
    expectNumbers(words, "normal");
    expect(words, "outer");
    expect(words, "loop");
    for (int corner = 0; corner < 3; ++corner)
    {
      expect(words, "vertex");
      expectNumbers(words, "vertex");
    }
    expect(words, "endloop");
    expect(words, "endfacet");
    ++facets;
  }
  if (facets == 0)
  {
    throw InputError(path, "no triangles (the ASCII STL file has no facets)");
  }
}

bool vtkReadsStlAsAscii(const std::string& head)
{
  const std::string first = head.substr(0, 256);
  std::size_t binary = 0;
  for (char c : first)
  {
    const auto byte = static_cast<unsigned char>(c);
    if (!((byte >= 0x20 && byte <= 0x7e) || c == '\n' || c == '\r' || c == '\t'))
    {
      ++binary;
    }
  }
  return !first.empty() && static_cast<double>(binary) / static_cast<double>(first.size()) < 0.05;
}

} // namespace proxima::detail
