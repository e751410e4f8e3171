#include "IO/Mesh/Private/VtpChecks.h"

#include "IO/InputChecks/InputError.h"

#include <fstream>
#include <iterator>

namespace proxima::detail
{
namespace
{
/// The value of attribute `name` in the tag text `tag` (quoted with " or '), or nothing.
bool attribute(const std::string& tag, const std::string& name, std::string& value)
{
  std::size_t at = 0;
  while ((at = tag.find(name, at)) != std::string::npos)
  {
    const bool wordStart = at > 0 && (tag[at - 1] == ' ' || tag[at - 1] == '\t' ||
                                      tag[at - 1] == '\n' || tag[at - 1] == '\r');
    std::size_t p = at + name.size();
    at = p;
    if (!wordStart)
    {
      continue;
    }
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t' || tag[p] == '\n' || tag[p] == '\r'))
    {
      ++p;
    }
    if (p >= tag.size() || tag[p] != '=')
    {
      continue;
    }
    ++p;
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t' || tag[p] == '\n' || tag[p] == '\r'))
    {
      ++p;
    }
    if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\''))
    {
      return false;
    }
    const std::size_t end = tag.find(tag[p], p + 1);
    if (end == std::string::npos)
    {
      return false;
    }
    value = tag.substr(p + 1, end - p - 1);
    return true;
  }
  return false;
}
} // namespace

void checkVtpPoints(const std::string& path)
{
  std::ifstream stream(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(stream)),
                         std::istreambuf_iterator<char>());
  // Appended binary data after <AppendedData> is not XML; the elements are all before it.
  const std::size_t appended = text.find("<AppendedData");
  const std::size_t limit = appended == std::string::npos ? text.size() : appended;
  std::size_t at = 0;
  std::size_t piece = 0;
  while ((at = text.find("<Points", at)) != std::string::npos && at < limit)
  {
    const std::size_t arrayStart = text.find("<DataArray", at);
    const std::size_t close = text.find("</Points", at);
    const std::string where =
      "not a valid VTK XML poly data file: the <Points> element " + std::to_string(piece);
    if (arrayStart == std::string::npos || (close != std::string::npos && close < arrayStart))
    {
      throw InputError(path, where + " has no DataArray");
    }
    const std::size_t arrayEnd = text.find('>', arrayStart);
    if (arrayEnd == std::string::npos)
    {
      throw InputError(path, where + ": its DataArray tag is not closed");
    }
    const std::string tag = text.substr(arrayStart, arrayEnd - arrayStart);
    std::string components;
    if (!attribute(tag, "NumberOfComponents", components))
    {
      throw InputError(path, where + ": its DataArray has no NumberOfComponents attribute (points "
                                     "need 3)");
    }
    if (components != "3")
    {
      throw InputError(path, where + ": its DataArray has NumberOfComponents=\"" +
                               components.substr(0, 20) + "\" (points need 3)");
    }
    at = arrayEnd;
    ++piece;
  }
}

} // namespace proxima::detail
