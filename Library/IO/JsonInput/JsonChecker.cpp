#include "IO/JsonInput/JsonChecker.h"

#include "IO/InputChecks/FileChecks.h"

#include <set>

namespace proxima
{
// `text` cut to at most `longest` bytes with " ..." at the end when it is longer, never inside a
// UTF-8 sequence (a message is printed whole on a terminal).
std::string cutShort(std::string text, std::size_t longest)
{
  if (text.size() <= longest)
  {
    return text;
  }
  std::size_t end = longest - 4;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0u) == 0x80u)
  {
    --end; // a continuation byte: back to the start of its character
  }
  text.resize(end);
  return text + " ...";
}

namespace
{
using Json = CheckedJson;

// nlohmann keeps the last of two equal keys without a word, which would hide a pasted line that
// overrides an earlier one; the parser callback sees every key, so repeats are refused there.
// It also tracks where in the document each event is, to say so.
class RepeatedKeyCheck
{
public:
  explicit RepeatedKeyCheck(const std::string& path)
    : m_path(path)
  {}

  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed)
  {
    using Event = Json::parse_event_t;
    switch (event)
    {
      case Event::object_start:
      case Event::array_start:
      case Event::value:
        if (!m_frames.empty() && m_frames.back().array)
        {
          ++m_frames.back().index;
        }
        if (event != Event::value)
        {
          m_frames.push_back(Frame{event == Event::array_start, -1, {}, {}});
        }
        break;
      case Event::key:
      {
        Frame& frame = m_frames.back();
        frame.key = parsed.get<std::string>();
        if (!frame.keys.insert(frame.key).second)
        {
          throw InputError(m_path, location() + ": the key appears twice in the same object");
        }
        break;
      }
      case Event::object_end:
      case Event::array_end: m_frames.pop_back(); break;
    }
    return true;
  }

private:
  struct Frame
  {
    bool array = false;
    long index = -1;
    std::string key;
    std::set<std::string> keys;
  };

  std::string location() const
  {
    std::string where;
    for (const Frame& frame : m_frames)
    {
      if (frame.array)
      {
        where += "[" + std::to_string(frame.index) + "]";
      }
      else
      {
        // A key written by mistake can be of any length; the message stays readable.
        where += (where.empty() ? "" : ".") + cutShort(frame.key, 40);
      }
    }
    return where;
  }

  const std::string& m_path;
  std::vector<Frame> m_frames;
};

Json parseJson(const std::string& path, const std::string& text)
{
  try
  {
    return Json::parse(text, RepeatedKeyCheck(path));
  }
  catch (const nlohmann::json::exception& error)
  {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..." keeps
    // its position and reason, without the library's prefix.
    std::string reason = error.what();
    const std::size_t bracket = reason.find("] ");
    if (bracket != std::string::npos)
    {
      reason.erase(0, bracket + 2);
    }
    const std::string_view at = "parse error at ";
    if (reason.starts_with(at))
    {
      reason.erase(0, at.size());
    }
    // The reason quotes the offending token, which may be a whole line of digits or a string.
    throw InputError(path, "not valid JSON: " + cutShort(reason, 160));
  }
}

// appendQuoted is quoted()'s.
// Compact JSON of `value`, as dump() writes it, but stopping once `out` is longer than `limit`
// and at a nesting depth of kMaxQuotedDepth: dump() recurses once per level, and a file of a
// hundred thousand nested brackets (which the parser itself takes without recursion) would
// overflow the stack while the message about it is written.
constexpr int kMaxQuotedDepth = 8;

void appendQuoted(const Json& value, std::size_t limit, int depth, std::string& out)
{
  if (!value.is_structured())
  {
    out += value.dump();
    return;
  }
  if (depth == kMaxQuotedDepth)
  {
    out += "...";
    return;
  }
  const bool array = value.is_array();
  out += array ? '[' : '{';
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it)
  {
    if (out.size() > limit)
    {
      return;
    }
    if (!first)
    {
      out += ',';
    }
    first = false;
    if (!array)
    {
      out += Json(it.key()).dump();
      out += ':';
    }
    appendQuoted(*it, limit, depth + 1, out);
  }
  out += array ? ']' : '}';
}

// The value as the file wrote it, cut short when long, for "got ..." in messages.
} // namespace

std::string JsonChecker::quoted(const Json& value)
{
  constexpr std::size_t kLongest = 40;
  std::string text;
  appendQuoted(value, kLongest, 0, text);
  return cutShort(std::move(text), kLongest);
}

std::size_t JsonChecker::editDistance(std::string_view a, std::string_view b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
  {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

CheckedJson readCheckedJsonFile(const std::string& path, const std::string& kind)
{
  return parseJson(path, detail::readWholeFile(path, kind));
}

} // namespace proxima
