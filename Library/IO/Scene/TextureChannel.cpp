#include "IO/Scene/TextureImageFile.h"

namespace proxima
{

const char* textureChannelName(TextureChannel channel)
{
  switch (channel)
  {
    case TextureChannel::Luminance: return "luminance";
    case TextureChannel::Red: return "red";
    case TextureChannel::Green: return "green";
    case TextureChannel::Blue: return "blue";
    case TextureChannel::Alpha: return "alpha";
  }
  return "unknown";
}

} // namespace proxima
