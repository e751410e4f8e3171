// The SpaceMouse report codecs against byte vectors written from the report layout: signed 16-bit
// little-endian axes after the report ID, buttons as a little-endian bit mask, the LED report,
// and report sizes from HID descriptor items.
#include "Devices/SpaceMouseReports.h"

#include <gtest/gtest.h>

#include <vector>

namespace proxima
{
namespace
{
using Bytes = std::vector<std::uint8_t>;

TEST(SpaceMouseReports, SplitLayoutTranslationAndRotation)
{
  SpaceMouseState state;
  // x = 16, y = -16 (0xfff0), z = 350 (0x015e).
  const Bytes translation{0x01, 0x10, 0x00, 0xf0, 0xff, 0x5e, 0x01};
  const auto t = applySpaceMouseReport(translation, SpaceMouseLayout::SplitReports, state);
  EXPECT_TRUE(t.accepted);
  EXPECT_TRUE(t.translation);
  EXPECT_FALSE(t.rotation);
  EXPECT_EQ(state.translation, (std::array<int, 3>{16, -16, 350}));
  // rx = -350 (0xfea2), ry = 0, rz = 1.
  const Bytes rotation{0x02, 0xa2, 0xfe, 0x00, 0x00, 0x01, 0x00};
  EXPECT_TRUE(applySpaceMouseReport(rotation, SpaceMouseLayout::SplitReports, state).accepted);
  EXPECT_EQ(state.rotation, (std::array<int, 3>{-350, 0, 1}));
  EXPECT_EQ(state.translation, (std::array<int, 3>{16, -16, 350}));
}

TEST(SpaceMouseReports, SixAxisLayoutHasEverythingInReportOne)
{
  SpaceMouseState state;
  const Bytes report{0x01, 0x01, 0x00, 0x02, 0x00, 0x03, 0x00, 0xff, 0xff, 0xfe, 0xff, 0x00, 0x80};
  const auto result = applySpaceMouseReport(report, SpaceMouseLayout::SixAxisReport, state);
  EXPECT_TRUE(result.accepted);
  EXPECT_TRUE(result.rotation);
  EXPECT_EQ(state.translation, (std::array<int, 3>{1, 2, 3}));
  EXPECT_EQ(state.rotation, (std::array<int, 3>{-1, -2, -32768}));
}

TEST(SpaceMouseReports, ButtonsAreALittleEndianMask)
{
  SpaceMouseState state;
  EXPECT_TRUE(
    applySpaceMouseReport(Bytes{0x03, 0x05, 0x01}, SpaceMouseLayout::SplitReports, state).accepted);
  EXPECT_EQ(state.buttons, 0x0105u);
}

TEST(SpaceMouseReports, ShortAndUnknownReportsAreRefusedAndChangeNothing)
{
  SpaceMouseState state;
  state.translation = {7, 8, 9};
  const Bytes shortSplit{0x01, 0x10, 0x00, 0xf0};
  auto result = applySpaceMouseReport(shortSplit, SpaceMouseLayout::SplitReports, state);
  EXPECT_FALSE(result.accepted);
  EXPECT_NE(result.error.find("report 1 has 3 bytes"), std::string::npos) << result.error;
  // Six bytes are enough for the split layout but short for the six-axis one.
  const Bytes sixBytes{0x01, 1, 0, 2, 0, 3, 0};
  EXPECT_FALSE(applySpaceMouseReport(sixBytes, SpaceMouseLayout::SixAxisReport, state).accepted);
  EXPECT_FALSE(
    applySpaceMouseReport(Bytes{0x02, 1, 0}, SpaceMouseLayout::SplitReports, state).accepted);
  EXPECT_FALSE(applySpaceMouseReport(Bytes{0x03}, SpaceMouseLayout::SplitReports, state).accepted);
  result = applySpaceMouseReport(Bytes{0x17, 0, 0}, SpaceMouseLayout::SplitReports, state);
  EXPECT_FALSE(result.accepted);
  EXPECT_EQ(result.error, "unknown report ID 23");
  EXPECT_FALSE(applySpaceMouseReport(Bytes{}, SpaceMouseLayout::SplitReports, state).accepted);
  EXPECT_EQ(state.translation, (std::array<int, 3>{7, 8, 9}));
  EXPECT_EQ(state.buttons, 0u);
}

TEST(SpaceMouseReports, LedReport)
{
  EXPECT_EQ(spaceMouseLedReport(true), (std::array<std::uint8_t, 2>{0x04, 0x01}));
  EXPECT_EQ(spaceMouseLedReport(false), (std::array<std::uint8_t, 2>{0x04, 0x00}));
}

// A descriptor of the split kind: Usage Page (Generic Desktop) 05 01, Usage (Multi-axis) 09 08,
// Collection (Application) a1 01; report 1: Report ID 85 01, Report Size 16 75 10, Report Count
// 3 95 03, Input 81 02; report 2 alike; report 3: Report Size 1 75 01, Count 16 95 10, Input;
// End Collection c0.
const Bytes kSplitDescriptor{0x05, 0x01, 0x09, 0x08, 0xa1, 0x01, 0x85, 0x01, 0x75, 0x10, 0x95,
                             0x03, 0x81, 0x02, 0x85, 0x02, 0x75, 0x10, 0x95, 0x03, 0x81, 0x02,
                             0x85, 0x03, 0x75, 0x01, 0x95, 0x10, 0x81, 0x02, 0xc0};

TEST(SpaceMouseDescriptor, InputReportSizesFromTheItems)
{
  std::string error;
  const auto sizes = inputReportSizes(kSplitDescriptor, error);
  ASSERT_TRUE(sizes) << error;
  using Sizes = std::vector<std::pair<std::uint8_t, std::size_t>>;
  EXPECT_EQ(*sizes, (Sizes{{1, 6}, {2, 6}, {3, 2}}));
  EXPECT_EQ(spaceMouseLayoutFromDescriptor(kSplitDescriptor, error),
            SpaceMouseLayout::SplitReports);
}

TEST(SpaceMouseDescriptor, SixAxisReportOne)
{
  // Report 1 with Report Count 6 (95 06): twelve bytes.
  const Bytes descriptor{0x05, 0x01, 0x09, 0x08, 0xa1, 0x01, 0x85, 0x01, 0x16, 0xa2, 0xfe,
                         0x26, 0x5e, 0x01, 0x75, 0x10, 0x95, 0x06, 0x81, 0x02, 0xc0};
  std::string error;
  EXPECT_EQ(spaceMouseLayoutFromDescriptor(descriptor, error), SpaceMouseLayout::SixAxisReport)
    << error;
}

TEST(SpaceMouseDescriptor, TruncatedOrForeignDescriptorsAreRefused)
{
  std::string error;
  // Report Count announces one data byte that is not there.
  const Bytes truncated{0x05, 0x01, 0x85, 0x01, 0x95};
  EXPECT_FALSE(inputReportSizes(truncated, error));
  EXPECT_NE(error.find("runs past the end"), std::string::npos) << error;
  // A keyboard-like descriptor: report 1 has one byte.
  const Bytes keyboard{0x85, 0x01, 0x75, 0x08, 0x95, 0x01, 0x81, 0x00};
  error.clear();
  EXPECT_FALSE(spaceMouseLayoutFromDescriptor(keyboard, error));
  EXPECT_NE(error.find("not a SpaceMouse"), std::string::npos);
}

} // namespace
} // namespace proxima
