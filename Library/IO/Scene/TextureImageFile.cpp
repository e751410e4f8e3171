// readTextureImage through OpenImageIO. Built into the module proxima-texture-images, which
// SceneIO loads the first time an image is read (TextureImageOnUse.cpp): OpenImageIO and its
// codecs are some 260 shared libraries, which a run without a texture should not load.
#include "IO/Scene/TextureImageFile.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/Scene/Private/PngChunks.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace proxima
{
namespace
{

// Beyond this many pixels a size is more likely a garbled header than a texture (8192 x 8192 is
// already far finer than a finger feels), and reading it could exhaust memory before any
// other check fails.
constexpr std::uint64_t kMaxPixels = std::uint64_t(1) << 26;

// The formats we promise, told apart by their first bytes so that OpenImageIO never falls back
// to trying every reader it has on a garbled file (some of which accept almost anything).
struct ImageFormat
{
  const char* plugin; // OpenImageIO's format name
  const char* name;   // for messages
};

std::optional<ImageFormat> formatFromSignature(const std::string& head)
{
  const auto startsWith = [&head](const char* bytes, std::size_t count) {
    return head.size() >= count && head.compare(0, count, bytes, count) == 0;
  };
  if (startsWith("\x89PNG\r\n\x1a\n", 8))
  {
    return ImageFormat{"png", "PNG"};
  }
  if (startsWith("\xff\xd8\xff", 3))
  {
    return ImageFormat{"jpeg", "JPEG"};
  }
  if (startsWith("II*\0", 4) || startsWith("MM\0*", 4) || startsWith("II+\0", 4) ||
      startsWith("MM\0+", 4))
  {
    return ImageFormat{"tiff", "TIFF"};
  }
  if (startsWith("\x76\x2f\x31\x01", 4))
  {
    return ImageFormat{"openexr", "OpenEXR"};
  }
  return std::nullopt;
}

// OpenImageIO keeps errors until asked, and complains on stderr about any never retrieved:
// every failure path takes the message from here.
std::string takeError(const OIIO::ImageInput* input)
{
  std::string message = input ? input->geterror() : std::string();
  const std::string global = OIIO::geterror();
  if (message.empty())
  {
    message = global;
  }
  return message.empty() ? std::string("unknown error") : message;
}

std::string channelList(const OIIO::ImageSpec& spec)
{
  std::string list;
  for (int c = 0; c < spec.nchannels; ++c)
  {
    const std::string name = c < int(spec.channelnames.size()) ? spec.channelnames[c] : "?";
    list += (c ? ", " : "") + name;
  }
  return list;
}

int findChannel(const OIIO::ImageSpec& spec, const char* name)
{
  for (int c = 0; c < int(spec.channelnames.size()) && c < spec.nchannels; ++c)
  {
    if (spec.channelnames[c] == name)
    {
      return c;
    }
  }
  return -1;
}

// The source channels of the texture and their weights.
struct ChannelPlan
{
  int indices[3] = {-1, -1, -1};
  double weights[3] = {0.0, 0.0, 0.0};
  int count = 0;
};

ChannelPlan planChannels(const std::string& path, const OIIO::ImageSpec& spec,
                         TextureChannel channel)
{
  const int alpha = spec.alpha_channel >= 0 ? spec.alpha_channel : findChannel(spec, "A");
  // R, G, B by name (EXR may order or name layers freely), else the first three channels that are
  // not alpha, OpenImageIO's order for PNG, JPEG and TIFF.
  std::vector<int> colour;
  const int named[3] = {findChannel(spec, "R"), findChannel(spec, "G"), findChannel(spec, "B")};
  if (named[0] >= 0 && named[1] >= 0 && named[2] >= 0)
  {
    colour.assign(named, named + 3);
  }
  else
  {
    for (int c = 0; c < spec.nchannels; ++c)
    {
      if (c != alpha)
      {
        colour.push_back(c);
      }
    }
  }
  const bool grey = colour.size() == 1;
  const bool rgb = colour.size() >= 3;
  const auto refuse = [&](const std::string& what) {
    throw InputError(path, "has no " + what + " for a " + textureChannelName(channel) +
                             " texture (channels: " + channelList(spec) + ")");
  };

  ChannelPlan plan;
  switch (channel)
  {
    case TextureChannel::Luminance:
      if (grey)
      {
        plan.indices[0] = colour[0];
        plan.weights[0] = 1.0;
        plan.count = 1;
      }
      else if (rgb)
      {
        // Rec. 709 (and sRGB) luminance weights, applied to the stored values as they are.
        const double weights[3] = {0.2126, 0.7152, 0.0722};
        for (int k = 0; k < 3; ++k)
        {
          plan.indices[k] = colour[k];
          plan.weights[k] = weights[k];
        }
        plan.count = 3;
      }
      else
      {
        refuse("single grey channel and no red, green and blue channels");
      }
      break;
    case TextureChannel::Red:
    case TextureChannel::Green:
    case TextureChannel::Blue:
    {
      // By name where the image names it (an EXR of R and G only), else by position in RGB.
      const int k = channel == TextureChannel::Red ? 0 : channel == TextureChannel::Green ? 1 : 2;
      plan.indices[0] = named[k] >= 0 ? named[k] : rgb ? colour[std::size_t(k)] : -1;
      if (plan.indices[0] < 0)
      {
        refuse(std::string(textureChannelName(channel)) + " channel");
      }
      plan.weights[0] = 1.0;
      plan.count = 1;
      break;
    }
    case TextureChannel::Alpha:
      if (alpha < 0)
      {
        refuse("alpha channel");
      }
      plan.indices[0] = alpha;
      plan.weights[0] = 1.0;
      plan.count = 1;
      break;
  }
  return plan;
}

} // namespace

TextureImage readTextureImage(const std::string& path, TextureChannel channel)
{
  detail::requireReadableFile(path, "image file");
  const std::optional<ImageFormat> format = formatFromSignature(detail::readFileHead(path, 8));
  if (!format)
  {
    throw InputError(path, "is not a PNG, JPEG, TIFF or OpenEXR image (unrecognised first bytes)");
  }

  if (std::string(format->plugin) == "png")
  {
    detail::checkPngChunks(path);
  }

  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(format->plugin);
  if (!input)
  {
    throw InputError(path, std::string("this build of OpenImageIO cannot read ") + format->name +
                             " (" + takeError(nullptr) + ")");
  }
  // Colour as stored, not multiplied by alpha: OpenImageIO would otherwise premultiply PNG and
  // TIFF colour on reading, and a bump map with an alpha channel would come back scaled by it.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  OIIO::ImageSpec spec;
  if (!input->open(path, spec, config))
  {
    throw InputError(path, std::string("cannot read the ") + format->name + " image (" +
                             takeError(input.get()) + ")");
  }
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
  {
    (void)input->geterror();
    input->close();
    throw InputError(path, "has no pixels");
  }
  if (spec.depth > 1)
  {
    input->close();
    throw InputError(path, "is a volume of " + std::to_string(spec.depth) +
                             " slices, not a flat texture image");
  }
  const std::uint64_t pixels = std::uint64_t(spec.width) * std::uint64_t(spec.height);
  if (pixels > kMaxPixels)
  {
    input->close();
    throw InputError(path, "is " + std::to_string(spec.width) + " x " +
                             std::to_string(spec.height) + " pixels, more than the " +
                             std::to_string(kMaxPixels) + " a texture image may have");
  }
  const ChannelPlan plan = planChannels(path, spec, channel);

  // Read only the span of channels the texture needs, converted to float: OpenImageIO maps
  // unsigned integers to [0, 1] and leaves half and float samples as stored.
  int chbegin = plan.indices[0];
  int chend = plan.indices[0] + 1;
  for (int k = 1; k < plan.count; ++k)
  {
    chbegin = std::min(chbegin, plan.indices[k]);
    chend = std::max(chend, plan.indices[k] + 1);
  }
  const std::size_t span = std::size_t(chend - chbegin);
  const std::size_t width = std::size_t(spec.width);
  const std::size_t height = std::size_t(spec.height);
  std::vector<float> pixelsRead(width * height * span);
  if (!input->read_image(0, 0, chbegin, chend, OIIO::TypeDesc::FLOAT, pixelsRead.data()))
  {
    const std::string message = takeError(input.get());
    input->close();
    throw InputError(path, std::string("cannot read the ") + format->name +
                             " pixels, the file may be truncated or damaged (" + message + ")");
  }
  // Some readers report a damaged file as a warning and carry on with filler pixels.
  if (input->has_error())
  {
    const std::string message = takeError(input.get());
    input->close();
    throw InputError(path, std::string("damaged ") + format->name + " data (" + message + ")");
  }
  input->close();
  (void)input->geterror();

  std::vector<float> values(width * height);
  for (std::size_t y = 0; y < height; ++y)
  {
    // Scanline 0 of the file is the top of the picture; row 0 of a texture is v = 0, the bottom.
    const std::size_t row = height - 1 - y;
    for (std::size_t x = 0; x < width; ++x)
    {
      const float* pixel = pixelsRead.data() + (y * width + x) * span;
      double value = 0.0;
      for (int k = 0; k < plan.count; ++k)
      {
        value += plan.weights[k] * double(pixel[plan.indices[k] - chbegin]);
      }
      // A luminance of huge floats can overflow a float even when every sample is finite.
      if (!(std::fabs(value) <= double(std::numeric_limits<float>::max())))
      {
        std::ostringstream out;
        out << "the " << textureChannelName(channel) << " value at pixel (" << x << ", " << y
            << ") from the top left is not finite (" << value << ")";
        throw InputError(path, out.str());
      }
      values[row * width + x] = static_cast<float>(value);
    }
  }
  return TextureImage(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height),
                      std::move(values));
}

} // namespace proxima
