// readTextureImage on images this test writes with OpenImageIO (so the expected texels are known
// exactly): 8-bit PNG, 16-bit TIFF, float OpenEXR, and JPEG within its lossy tolerance; the row
// flip (row 0 of a texture is the bottom of the picture); the channel choices; the shared
// spot_texture.png; and bad files, each refused with a one-line InputError naming the file.
#include "IO/Scene/TextureImageFile.h"

#include "IO/Testing/ScratchFolderTest.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using proxima::TextureChannel;
using proxima::TextureImage;

constexpr int kWidth = 5;
constexpr int kHeight = 3;

// Channel c of the picture's pixel (x, y), y counted from the top, as a value in [0, 1]: distinct
// per pixel and channel, so that a swapped row, column or channel shows.
double pictureValue(int x, int y, int c)
{
  return (1 + x + kWidth * y + kWidth * kHeight * c) / 64.0;
}

class TextureImageFile : public proxima::testing_support::ScratchFolderTest
{
protected:
  TextureImageFile()
    : ScratchFolderTest("proxima-texture-")
  {}

  /// Writes the kWidth x kHeight picture with `channels` channels in `type` (values rounded by
  /// OpenImageIO's conversion from float) and returns its path.
  std::string writePicture(const std::string& name, int channels, OIIO::TypeDesc type,
                           std::ptrdiff_t nanIndex = -1) const
  {
    std::vector<float> pixels(std::size_t(kWidth) * kHeight * channels);
    for (int y = 0; y < kHeight; ++y)
    {
      for (int x = 0; x < kWidth; ++x)
      {
        for (int c = 0; c < channels; ++c)
        {
          pixels[(std::size_t(y) * kWidth + x) * channels + c] = float(pictureValue(x, y, c));
        }
      }
    }
    if (nanIndex >= 0)
    {
      pixels[std::size_t(nanIndex)] = std::numeric_limits<float>::quiet_NaN();
    }
    const std::string path = pathOf(name);
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(output) << OIIO::geterror();
    OIIO::ImageSpec spec(kWidth, kHeight, channels, type);
    // Store colour as given, not divided by alpha as OpenImageIO does by default for PNG.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (name.ends_with(".jpg"))
    {
      spec.attribute("Compression", "jpeg:100");
    }
    EXPECT_TRUE(output->open(path, spec)) << output->geterror();
    EXPECT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << output->geterror();
    EXPECT_TRUE(output->close()) << output->geterror();
    return path;
  }

  std::string writeBytes(const std::string& name, const std::string& bytes) const
  {
    const std::string path = pathOf(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  static std::string readBytes(const std::string& path)
  {
    std::ifstream stream(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>());
  }

  /// Reads `path` and expects a one-line InputError naming it and containing `defect`, with
  /// nothing printed on stderr meanwhile.
  static void expectRefused(const std::string& path, const std::string& defect,
                            TextureChannel channel = TextureChannel::Luminance)
  {
    testing::internal::CaptureStderr();
    std::string message;
    try
    {
      (void)proxima::readTextureImage(path, channel);
    }
    catch (const proxima::InputError& error)
    {
      message = error.what();
      EXPECT_EQ(error.path(), path);
    }
    const std::string printed = testing::internal::GetCapturedStderr();
    ASSERT_FALSE(message.empty()) << path << " was accepted";
    EXPECT_NE(message.find(fs::path(path).filename().string()), std::string::npos) << message;
    EXPECT_NE(message.find(defect), std::string::npos)
      << "wanted '" << defect << "' in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(printed, "") << "printed while reading " << path;
  }

  /// Expects texel (x, kHeight - 1 - y) of `image` to be `expected(x, y)` within `tolerance`.
  template <typename Expected>
  static void expectFlipped(const TextureImage& image, Expected expected, double tolerance)
  {
    ASSERT_EQ(image.width(), std::uint32_t(kWidth));
    ASSERT_EQ(image.height(), std::uint32_t(kHeight));
    for (int y = 0; y < kHeight; ++y)
    {
      for (int x = 0; x < kWidth; ++x)
      {
        EXPECT_NEAR(image.texel(x, kHeight - 1 - y), expected(x, y), tolerance)
          << "picture pixel (" << x << ", " << y << ") from the top left";
      }
    }
  }
};

double rounded(double value, double levels)
{
  return std::round(value * levels) / levels;
}

// OpenImageIO normalises k by multiplying with 1 / 255 (or 1 / 65535) in float, which may land
// one float ulp from the float nearest k / 255; the levels themselves are 4e-3 (1.5e-5) apart.
constexpr double kIntegerRounding = 1.2e-7;

TEST_F(TextureImageFile, IntegerExtremesAreZeroAndOne)
{
  for (const auto& [name, type] : {std::pair{"extremes.png", OIIO::TypeDesc::UINT8},
                                   std::pair{"extremes.tif", OIIO::TypeDesc::UINT16}})
  {
    const std::string path = pathOf(name);
    const float pixels[2] = {0.0f, 1.0f};
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(output);
    ASSERT_TRUE(output->open(path, OIIO::ImageSpec(2, 1, 1, type)));
    ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, pixels));
    ASSERT_TRUE(output->close());
    const TextureImage image = proxima::readTextureImage(path);
    EXPECT_EQ(image.texel(0, 0), 0.0f) << name;
    EXPECT_EQ(image.texel(1, 0), 1.0f) << name;
  }
}

TEST_F(TextureImageFile, Png8BitRgbaChannelsAndLuminance)
{
  const std::string path = writePicture("picture.png", 4, OIIO::TypeDesc::UINT8);
  // Each channel is the 8-bit value over 255, exactly as a float.
  const auto channel = [](int c) {
    return [c](int x, int y) { return double(float(rounded(pictureValue(x, y, c), 255.0))); };
  };
  expectFlipped(proxima::readTextureImage(path, TextureChannel::Red), channel(0), kIntegerRounding);
  expectFlipped(proxima::readTextureImage(path, TextureChannel::Green), channel(1),
                kIntegerRounding);
  expectFlipped(proxima::readTextureImage(path, TextureChannel::Blue), channel(2),
                kIntegerRounding);
  expectFlipped(
    proxima::readTextureImage(path),
    [&](int x, int y) {
      return 0.2126 * channel(0)(x, y) + 0.7152 * channel(1)(x, y) + 0.0722 * channel(2)(x, y);
    },
    1e-7);
  // Alpha is a channel of its own and does not scale the colour.
  expectFlipped(proxima::readTextureImage(path, TextureChannel::Alpha), channel(3),
                kIntegerRounding);
}

TEST_F(TextureImageFile, PngGreyWithAlpha)
{
  const std::string path = writePicture("grey-alpha.png", 2, OIIO::TypeDesc::UINT8);
  const auto channel = [](int c) {
    return [c](int x, int y) { return double(float(rounded(pictureValue(x, y, c), 255.0))); };
  };
  expectFlipped(proxima::readTextureImage(path), channel(0), kIntegerRounding);
  expectFlipped(proxima::readTextureImage(path, TextureChannel::Alpha), channel(1),
                kIntegerRounding);
  expectRefused(path, "has no red channel", TextureChannel::Red);
}

TEST_F(TextureImageFile, Tiff16BitGrey)
{
  const std::string path = writePicture("picture.tif", 1, OIIO::TypeDesc::UINT16);
  expectFlipped(
    proxima::readTextureImage(path),
    [](int x, int y) { return double(float(rounded(pictureValue(x, y, 0), 65535.0))); },
    kIntegerRounding);
  expectRefused(path, "has no green channel", TextureChannel::Green);
}

TEST_F(TextureImageFile, ExrFloatKeepsStoredValues)
{
  // Floats are not normalised: values above 1 and below 0 come through as stored.
  const std::string path = pathOf("picture.exr");
  std::vector<float> pixels(std::size_t(kWidth) * kHeight * 4);
  for (std::size_t k = 0; k < pixels.size(); ++k)
  {
    pixels[k] = float(k) * 0.37f - 7.0f;
  }
  {
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(output);
    OIIO::ImageSpec spec(kWidth, kHeight, 4, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(output->open(path, spec)) << output->geterror();
    ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << output->geterror();
    ASSERT_TRUE(output->close());
  }
  const auto stored = [&](int c) {
    return [&, c](int x, int y) { return double(pixels[(std::size_t(y) * kWidth + x) * 4 + c]); };
  };
  expectFlipped(proxima::readTextureImage(path, TextureChannel::Red), stored(0), 0.0);
  expectFlipped(proxima::readTextureImage(path, TextureChannel::Blue), stored(2), 0.0);
  expectFlipped(proxima::readTextureImage(path, TextureChannel::Alpha), stored(3), 0.0);
  expectFlipped(
    proxima::readTextureImage(path),
    [&](int x, int y) {
      return 0.2126 * stored(0)(x, y) + 0.7152 * stored(1)(x, y) + 0.0722 * stored(2)(x, y);
    },
    1e-5);
}

TEST_F(TextureImageFile, JpegWithinItsLossyTolerance)
{
  const std::string path = writePicture("picture.jpg", 3, OIIO::TypeDesc::UINT8);
  // Quality 100 still rounds through YCbCr and the DCT: a few levels of 255.
  expectFlipped(
    proxima::readTextureImage(path, TextureChannel::Green),
    [](int x, int y) { return pictureValue(x, y, 1); }, 6.0 / 255.0);
  expectRefused(path, "has no alpha channel", TextureChannel::Alpha);
}

TEST_F(TextureImageFile, ContentDecidesTheFormatNotTheExtension)
{
  const std::string png = writePicture("picture.png", 1, OIIO::TypeDesc::UINT8);
  const std::string misnamed = writeBytes("picture.tif", readBytes(png));
  expectFlipped(
    proxima::readTextureImage(misnamed),
    [](int x, int y) { return double(float(rounded(pictureValue(x, y, 0), 255.0))); },
    kIntegerRounding);
}

TEST_F(TextureImageFile, SharedSpotTexture)
{
  const fs::path path = fs::path(PROXIMA_SHARED_MESHES) / "spot_texture.png";
  if (!fs::exists(path))
  {
    GTEST_SKIP() << "shared texture " << path << " is absent (see PROXIMA_SHARED_DATA)";
  }
  testing::internal::CaptureStderr();
  const TextureImage image = proxima::readTextureImage(path.string());
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(image.width(), 1024u);
  EXPECT_EQ(image.height(), 1024u);
  double lowest = 1.0, highest = 0.0;
  for (std::uint32_t j = 0; j < image.height(); ++j)
  {
    for (std::uint32_t i = 0; i < image.width(); ++i)
    {
      lowest = std::min(lowest, double(image.texel(i, j)));
      highest = std::max(highest, double(image.texel(i, j)));
    }
  }
  EXPECT_GE(lowest, 0.0);
  EXPECT_LE(highest, 1.0);
  EXPECT_LT(lowest, highest) << "a real picture is not flat";
  // RGB without alpha.
  EXPECT_NO_THROW((void)proxima::readTextureImage(path.string(), TextureChannel::Red));
  expectRefused(path.string(), "has no alpha channel", TextureChannel::Alpha);
}

TEST_F(TextureImageFile, MissingFile)
{
  expectRefused(pathOf("absent.png"), "cannot open");
}

TEST_F(TextureImageFile, Directory)
{
  expectRefused(m_dir.string(), "is a directory");
}

TEST_F(TextureImageFile, EmptyFile)
{
  expectRefused(writeBytes("empty.png", ""), "empty");
}

TEST_F(TextureImageFile, GarbageWithPngName)
{
  std::string bytes(4096, '\0');
  std::uint32_t state = 12345u;
  for (char& c : bytes)
  {
    state = state * 1664525u + 1013904223u;
    c = static_cast<char>(state >> 24);
  }
  expectRefused(writeBytes("garbage.png", bytes), "is not a PNG, JPEG, TIFF or OpenEXR image");
}

TEST_F(TextureImageFile, PngSignatureThenGarbage)
{
  std::string bytes = "\x89PNG\r\n\x1a\n";
  bytes += std::string(200, 'x');
  expectRefused(writeBytes("garbled.png", bytes), "garbled PNG");
}

TEST_F(TextureImageFile, TruncatedPng)
{
  // A picture large enough that its pixel data spans many bytes, cut in the middle of them.
  const std::string path = pathOf("whole.png");
  {
    const int size = 64;
    std::vector<unsigned char> pixels(std::size_t(size) * size * 3);
    std::uint32_t state = 7u;
    for (unsigned char& p : pixels)
    {
      state = state * 1664525u + 1013904223u;
      p = static_cast<unsigned char>(state >> 24);
    }
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(output);
    ASSERT_TRUE(output->open(path, OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(output->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    ASSERT_TRUE(output->close());
  }
  const std::string whole = readBytes(path);
  ASSERT_GT(whole.size(), 4000u);
  EXPECT_NO_THROW((void)proxima::readTextureImage(path));
  expectRefused(writeBytes("truncated.png", whole.substr(0, whole.size() / 2)), "truncated");
  // Cut inside the header chunk, before any pixel.
  expectRefused(writeBytes("header-only.png", whole.substr(0, 20)), "truncated PNG");
}

TEST_F(TextureImageFile, TruncatedAnywhere)
{
  // Every format cut at several places: in the header, in the pixels, just before the end.
  const int size = 64;
  std::vector<float> pixels(std::size_t(size) * size * 3);
  std::uint32_t state = 3u;
  for (float& p : pixels)
  {
    state = state * 1664525u + 1013904223u;
    p = float(state >> 8) / float(1u << 24);
  }
  for (const std::string name : {"whole.png", "whole.tif", "whole.exr", "whole.jpg"})
  {
    const std::string path = pathOf(name);
    {
      std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
      ASSERT_TRUE(output);
      const OIIO::TypeDesc type =
        name.ends_with(".exr") ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8;
      ASSERT_TRUE(output->open(path, OIIO::ImageSpec(size, size, 3, type)));
      ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
      ASSERT_TRUE(output->close());
    }
    const std::string whole = readBytes(path);
    EXPECT_NO_THROW((void)proxima::readTextureImage(path)) << name;
    for (const double fraction : {0.01, 0.25, 0.5, 0.75, 0.99})
    {
      const std::size_t cut =
        std::max<std::size_t>(4, std::size_t(fraction * double(whole.size())));
      expectRefused(writeBytes(std::to_string(cut) + "-" + name, whole.substr(0, cut)), "");
    }
    expectRefused(writeBytes("last-byte-" + name, whole.substr(0, whole.size() - 1)), "");
  }
}

TEST_F(TextureImageFile, TwoColourChannels)
{
  // R and G only: no luminance, but the named channels are there.
  const std::string path = writePicture("rg.exr", 2, OIIO::TypeDesc::FLOAT);
  expectRefused(path, "has no single grey channel");
  expectFlipped(
    proxima::readTextureImage(path, TextureChannel::Green),
    [](int x, int y) { return double(float(pictureValue(x, y, 1))); }, 0.0);
  expectRefused(path, "has no blue channel", TextureChannel::Blue);
}

TEST_F(TextureImageFile, ExrWithNan)
{
  // The NaN in pixel (2, 1) from the top left, red channel of an RGB image.
  const std::string path = writePicture("nan.exr", 3, OIIO::TypeDesc::FLOAT, (1 * kWidth + 2) * 3);
  expectRefused(path, "is not finite");
  expectRefused(path, "pixel (2, 1)", TextureChannel::Red);
  // A texture that does not use the bad channel is fine.
  EXPECT_NO_THROW((void)proxima::readTextureImage(path, TextureChannel::Green));
}

} // namespace
