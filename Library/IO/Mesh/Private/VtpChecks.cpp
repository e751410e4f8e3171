#include "IO/Mesh/Private/VtpChecks.h"

#include "IO/InputChecks/InputError.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>

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
constexpr std::uint64_t kNoCount = std::numeric_limits<std::uint64_t>::max();

/// `text` as an unsigned decimal count, or kNoCount.
std::uint64_t count(const std::string& text)
{
  if (text.empty() || text.size() > 19 || text.find_first_not_of("0123456789") != std::string::npos)
  {
    return kNoCount;
  }
  return std::stoull(text);
}

/// The six bits of base64 character `c`, or -1.
int base64Value(char c)
{
  if (c >= 'A' && c <= 'Z')
  {
    return c - 'A';
  }
  if (c >= 'a' && c <= 'z')
  {
    return c - 'a' + 26;
  }
  if (c >= '0' && c <= '9')
  {
    return c - '0' + 52;
  }
  return c == '+' ? 62 : (c == '/' ? 63 : -1);
}

/// How the file stores its binary arrays (the VTKFile element's attributes).
struct VtpLayout
{
  std::uint64_t wordBytes = 4;
  bool littleEndian = true;
  bool compressed = false;
  /// The most one byte of the file can stand for once decompressed: zlib's deflate stores at
  /// most about 1032 bytes in one, LZ4 255; LZMA's long matches go further, bounded here
  /// generously. 1 without a compressor.
  std::uint64_t expansion = 1;
};

/// Reads the binary array header words that start at `text[at]` (raw bytes, or base64 text when
/// `base64`): `words` of them. False when the file ends first.
bool headerWords(const std::string& text, std::size_t at, bool base64, const VtpLayout& layout,
                 int words, std::uint64_t* values)
{
  const std::size_t bytes = static_cast<std::size_t>(words) * layout.wordBytes;
  std::string raw;
  if (base64)
  {
    std::uint32_t bits = 0;
    int held = 0;
    for (std::size_t i = at; i < text.size() && raw.size() < bytes; ++i)
    {
      const int value = base64Value(text[i]);
      if (value < 0)
      {
        if (text[i] == '=' || text[i] == '<')
        {
          break;
        }
        continue; // whitespace between the lines of base64
      }
      bits = (bits << 6) | static_cast<std::uint32_t>(value);
      held += 6;
      if (held >= 8)
      {
        held -= 8;
        raw.push_back(static_cast<char>((bits >> held) & 0xFFu));
      }
    }
  }
  else if (at <= text.size())
  {
    raw = text.substr(at, bytes);
  }
  if (raw.size() < bytes)
  {
    return false;
  }
  for (int w = 0; w < words; ++w)
  {
    std::uint64_t value = 0;
    for (std::uint64_t b = 0; b < layout.wordBytes; ++b)
    {
      const std::uint64_t index = layout.littleEndian ? layout.wordBytes - 1 - b : b;
      value = (value << 8) | static_cast<unsigned char>(
                               raw[static_cast<std::size_t>(w * layout.wordBytes + index)]);
    }
    values[w] = value;
  }
  return true;
}

/// Checks the header of one binary array whose data start at `text[at]`, with `available`
/// bytes of (decoded) data from there to the end of the file.
void checkArrayHeader(const std::string& path, const std::string& where, const std::string& text,
                      std::size_t at, bool base64, const VtpLayout& layout, std::uint64_t available)
{
  const std::uint64_t limit = layout.expansion * static_cast<std::uint64_t>(text.size());
  if (!layout.compressed)
  {
    std::uint64_t bytes = 0;
    if (!headerWords(text, at, base64, layout, 1, &bytes))
    {
      throw InputError(path, where + ": the file ends inside its header");
    }
    if (bytes > available)
    {
      throw InputError(path, where + " declares " + std::to_string(bytes) +
                               " bytes of data but the file has " + std::to_string(available) +
                               " after it");
    }
    return;
  }
  // A compressed array: block count, block size, size of the last block, then one compressed
  // size per block (vtkXMLDataParser reads them all, then allocates a block).
  std::uint64_t words[3] = {0, 0, 0};
  if (!headerWords(text, at, base64, layout, 3, words))
  {
    throw InputError(path, where + ": the file ends inside its compression header");
  }
  const std::uint64_t blocks = words[0];
  const std::uint64_t blockSize = words[1];
  if (blocks > available / layout.wordBytes)
  {
    throw InputError(path, where + "'s compression header declares " + std::to_string(blocks) +
                             " blocks but the file has " + std::to_string(available) +
                             " bytes after it");
  }
  if (blockSize > limit || (blocks > 0 && blockSize > 0 && blocks - 1 > limit / blockSize))
  {
    throw InputError(path, where + "'s compression header declares " + std::to_string(blocks) +
                             " blocks of " + std::to_string(blockSize) +
                             " bytes, more than a file of " + std::to_string(text.size()) +
                             " bytes can hold compressed");
  }
}

/// The VTKFile element's layout, refusing attributes VTK would misread.
VtpLayout layoutOf(const std::string& path, const std::string& text)
{
  VtpLayout layout;
  const std::size_t start = text.find("<VTKFile");
  if (start == std::string::npos)
  {
    return layout; // the reader refuses it with its own message
  }
  const std::string tag = text.substr(start, text.find('>', start) - start);
  std::string value;
  if (attribute(tag, "header_type", value))
  {
    if (value != "UInt32" && value != "UInt64")
    {
      throw InputError(path, "not a valid VTK XML poly data file: header_type \"" +
                               value.substr(0, 20) + "\" (UInt32 or UInt64)");
    }
    layout.wordBytes = value == "UInt64" ? 8 : 4;
  }
  layout.littleEndian = !(attribute(tag, "byte_order", value) && value == "BigEndian");
  if (attribute(tag, "compressor", value) && !value.empty())
  {
    layout.compressed = true;
    layout.expansion =
      value == "vtkZLibDataCompressor" ? 1100 : (value == "vtkLZ4DataCompressor" ? 256 : 100000);
  }
  return layout;
}
} // namespace

void checkVtpDeclaredSizes(const std::string& path)
{
  std::ifstream stream(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(stream)),
                         std::istreambuf_iterator<char>());
  const VtpLayout layout = layoutOf(path, text);
  const std::size_t appended = text.find("<AppendedData");
  const std::size_t limit = appended == std::string::npos ? text.size() : appended;
  const std::uint64_t most = layout.expansion * static_cast<std::uint64_t>(text.size());

  // Every value takes a byte of the file at least, before decompression: three a point, and a
  // connectivity entry and an offset a cell.
  std::uint64_t values = 0;
  std::size_t at = 0;
  while ((at = text.find("<Piece", at)) != std::string::npos && at < limit)
  {
    const std::string tag = text.substr(at, text.find('>', at) - at);
    for (const char* name :
         {"NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
    {
      std::string value;
      if (!attribute(tag, name, value))
      {
        continue;
      }
      const std::uint64_t n = count(value);
      const std::uint64_t perItem = std::string(name) == "NumberOfPoints" ? 3 : 2;
      if (n == kNoCount || n > most / perItem || values + n * perItem > most)
      {
        throw InputError(path,
                         std::string("not a valid VTK XML poly data file: its pieces declare ") +
                           name + "=\"" + value.substr(0, 24) + "\", more than a file of " +
                           std::to_string(text.size()) + " bytes can hold");
      }
      values += n * perItem;
    }
    at += tag.size();
  }

  // The appended section's data start after its '_'.
  std::size_t appendedData = std::string::npos;
  bool appendedBase64 = true;
  if (appended != std::string::npos)
  {
    const std::string tag = text.substr(appended, text.find('>', appended) - appended);
    std::string encoding;
    appendedBase64 = !(attribute(tag, "encoding", encoding) && encoding == "raw");
    const std::size_t underscore = text.find('_', appended + tag.size());
    appendedData = underscore == std::string::npos ? std::string::npos : underscore + 1;
  }

  std::size_t index = 0;
  at = 0;
  while ((at = text.find("<DataArray", at)) != std::string::npos && at < limit)
  {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos)
    {
      break; // the reader refuses the unclosed tag
    }
    const std::string tag = text.substr(at, end - at);
    const std::string where =
      "not a valid VTK XML poly data file: DataArray " + std::to_string(index++);
    std::string format;
    attribute(tag, "format", format);
    if (format == "binary")
    {
      std::size_t data = end + 1;
      while (data < text.size() && base64Value(text[data]) < 0 && text[data] != '<')
      {
        ++data;
      }
      const std::size_t close = text.find('<', data);
      const std::uint64_t characters = (close == std::string::npos ? text.size() : close) - data;
      checkArrayHeader(path, where, text, data, true, layout, characters / 4 * 3 + 3);
    }
    else if (format == "appended")
    {
      std::string offsetText;
      const std::uint64_t offset =
        attribute(tag, "offset", offsetText) ? count(offsetText) : kNoCount;
      if (appendedData == std::string::npos || offset == kNoCount ||
          offset > text.size() - appendedData)
      {
        throw InputError(path, where + "'s offset \"" + offsetText.substr(0, 24) +
                                 "\" is not inside the file's appended data");
      }
      const std::size_t data = appendedData + static_cast<std::size_t>(offset);
      const std::uint64_t remaining = text.size() - data;
      checkArrayHeader(path, where, text, data, appendedBase64, layout,
                       appendedBase64 ? remaining / 4 * 3 + 3 : remaining);
    }
    at = end;
  }
}

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
