#include "IO/Scene/Private/PngChunks.h"

#include "IO/InputChecks/InputError.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace proxima::detail
{
namespace
{

// CRC-32 of ISO 3309 as the PNG specification defines it (its annex D), table built once.
std::uint32_t updateCrc(std::uint32_t crc, const unsigned char* bytes, std::size_t count)
{
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n)
    {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k)
      {
        c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
      }
      t[n] = c;
    }
    return t;
  }();
  for (std::size_t k = 0; k < count; ++k)
  {
    crc = table[(crc ^ bytes[k]) & 0xffu] ^ (crc >> 8);
  }
  return crc;
}

std::uint32_t bigEndian(const unsigned char* bytes)
{
  return (std::uint32_t(bytes[0]) << 24) | (std::uint32_t(bytes[1]) << 16) |
         (std::uint32_t(bytes[2]) << 8) | std::uint32_t(bytes[3]);
}

bool isLetter(unsigned char c)
{
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

} // namespace

void checkPngChunks(const std::string& path)
{
  std::ifstream stream(path, std::ios::binary);
  stream.seekg(8); // past the signature
  std::vector<unsigned char> data;
  std::uint64_t offset = 8;
  for (int index = 0;; ++index)
  {
    unsigned char header[8];
    if (!stream.read(reinterpret_cast<char*>(header), 8))
    {
      throw InputError(path, "truncated PNG: the file ends at byte " +
                               std::to_string(offset + std::uint64_t(stream.gcount())) +
                               " without the IEND chunk that closes it");
    }
    const std::uint32_t length = bigEndian(header);
    const std::string type(reinterpret_cast<const char*>(header + 4), 4);
    if (!(isLetter(header[4]) && isLetter(header[5]) && isLetter(header[6]) && isLetter(header[7])))
    {
      throw InputError(path, "garbled PNG: the chunk at byte " + std::to_string(offset) +
                               " has no four-letter type");
    }
    if (index == 0 && (type != "IHDR" || length != 13))
    {
      throw InputError(path, "garbled PNG: the first chunk is not a 13-byte IHDR");
    }
    if (length > 0x7fffffffu)
    {
      throw InputError(path, "garbled PNG: the " + type + " chunk at byte " +
                               std::to_string(offset) + " claims " + std::to_string(length) +
                               " bytes, more than PNG allows");
    }
    data.resize(std::size_t(length) + 4);
    stream.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size()));
    if (std::size_t(stream.gcount()) != data.size())
    {
      throw InputError(path, "truncated PNG: the " + type + " chunk at byte " +
                               std::to_string(offset) + " needs " + std::to_string(length + 12) +
                               " bytes, the file ends after " +
                               std::to_string(offset + 8 + std::uint64_t(stream.gcount())));
    }
    std::uint32_t crc = updateCrc(0xffffffffu, header + 4, 4);
    crc = updateCrc(crc, data.data(), length) ^ 0xffffffffu;
    if (crc != bigEndian(data.data() + length))
    {
      throw InputError(path, "damaged PNG: the CRC of the " + type + " chunk at byte " +
                               std::to_string(offset) + " does not match its bytes");
    }
    if (type == "IEND")
    {
      return;
    }
    offset += std::uint64_t(length) + 12;
  }
}

} // namespace proxima::detail
