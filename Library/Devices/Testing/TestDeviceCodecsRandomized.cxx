// The device codecs on random input, fixed seeds: whatever bytes arrive, nothing is read past the
// end (AddressSanitizer in CI), a SpaceMouse report is accepted exactly when its ID and length
// allow it and then decodes as the bytes say, and every frame the Falcon frame reader returns is
// sixteen bytes that really came in a row in the stream.
#include "Devices/FalconFrame.h"
#include "Devices/SpaceMouseReports.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace proxima
{
namespace
{
TEST(DeviceCodecsRandomized, SpaceMouseReportsAcceptedExactlyWhenWellFormed)
{
  std::mt19937 random(23);
  for (int trial = 0; trial < 20000; ++trial)
  {
    std::vector<std::uint8_t> report(random() % 16);
    for (auto& byte : report)
    {
      byte = static_cast<std::uint8_t>(random());
    }
    if (!report.empty() && random() % 2 == 0)
    {
      report[0] = static_cast<std::uint8_t>(1 + random() % 4);
    }
    const SpaceMouseLayout layout =
      random() % 2 == 0 ? SpaceMouseLayout::SplitReports : SpaceMouseLayout::SixAxisReport;
    SpaceMouseState state;
    state.translation = {1, 2, 3};
    const auto result = applySpaceMouseReport(report, layout, state);
    const std::size_t payload = report.empty() ? 0 : report.size() - 1;
    const int id = report.empty() ? -1 : report[0];
    const bool wellFormed =
      (id == 1 && payload >= (layout == SpaceMouseLayout::SixAxisReport ? 12u : 6u)) ||
      (id == 2 && payload >= 6) || (id == 3 && payload >= 1);
    ASSERT_EQ(result.accepted, wellFormed) << "trial " << trial;
    if (id == 1 && wellFormed)
    {
      for (std::size_t axis = 0; axis < 3; ++axis)
      {
        std::int16_t value = 0;
        std::memcpy(&value, report.data() + 1 + 2 * axis, 2); // little-endian machine
        EXPECT_EQ(state.translation[axis], value);
      }
    }
    if (!wellFormed)
    {
      EXPECT_EQ(state.translation, (std::array<int, 3>{1, 2, 3}));
    }
  }
}

TEST(DeviceCodecsRandomized, DescriptorWalkerStaysInside)
{
  std::mt19937 random(29);
  int refused = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    std::vector<std::uint8_t> descriptor(random() % 40);
    for (auto& byte : descriptor)
    {
      byte = static_cast<std::uint8_t>(random());
    }
    std::string error;
    if (!inputReportSizes(descriptor, error))
    {
      ++refused;
      EXPECT_FALSE(error.empty());
    }
  }
  EXPECT_GT(refused, 1000);
}

TEST(DeviceCodecsRandomized, FrameReaderReturnsOnlyFramesThatCameInARow)
{
  std::mt19937 random(31);
  const std::string alphabet = "<>ABCDEFGHIJKLMNOP";
  for (int trial = 0; trial < 300; ++trial)
  {
    // A stream of good frames, noise and cut frames, fed in random pieces.
    std::vector<std::uint8_t> stream;
    while (stream.size() < 2000)
    {
      const unsigned kind = random() % 4;
      if (kind == 0)
      {
        FalconFrame frame;
        frame.values = {static_cast<std::int16_t>(random()), static_cast<std::int16_t>(random()),
                        static_cast<std::int16_t>(random())};
        frame.info = static_cast<std::uint8_t>(random() % 0x80);
        const auto bytes = encodeFalconFrame(frame);
        const std::size_t keep = random() % 3 == 0 ? random() % 16 : 16;
        stream.insert(stream.end(), bytes.begin(),
                      bytes.begin() + static_cast<std::ptrdiff_t>(keep));
      }
      else
      {
        const std::size_t noise = random() % 20;
        for (std::size_t i = 0; i < noise; ++i)
        {
          stream.push_back(kind == 1
                             ? static_cast<std::uint8_t>(random())
                             : static_cast<std::uint8_t>(alphabet[random() % alphabet.size()]));
        }
      }
    }
    FalconFrameReader reader;
    std::size_t at = 0;
    while (at < stream.size())
    {
      const std::size_t piece = std::min<std::size_t>(1 + random() % 40, stream.size() - at);
      const auto frame = reader.push(std::span<const std::uint8_t>(stream.data() + at, piece));
      at += piece;
      if (frame)
      {
        const auto bytes = encodeFalconFrame(*frame);
        const auto found =
          std::search(stream.begin(), stream.begin() + static_cast<std::ptrdiff_t>(at),
                      bytes.begin(), bytes.end());
        ASSERT_NE(found, stream.begin() + static_cast<std::ptrdiff_t>(at)) << "trial " << trial;
      }
    }
  }
}

} // namespace
} // namespace proxima
