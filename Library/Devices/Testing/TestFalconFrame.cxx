// The Falcon frame codec against byte strings written from libnifalcon's description: '<', three
// values as four 'A'-offset nibbles each (low nibble first), info and reserved as 'A' + value,
// '>'.
#include "Devices/FalconFrame.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace proxima
{
namespace
{
std::vector<std::uint8_t> bytesOf(const std::string& text)
{
  return {text.begin(), text.end()};
}

TEST(FalconFrame, ZeroFrameIsAllA)
{
  const FalconFrameBytes bytes = encodeFalconFrame(FalconFrame{});
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "<AAAAAAAAAAAAAA>");
  std::string error;
  const auto frame = decodeFalconFrame(bytesOf("<AAAAAAAAAAAAAA>"), error);
  ASSERT_TRUE(frame) << error;
  EXPECT_EQ(frame->values, (std::array<std::int16_t, 3>{0, 0, 0}));
  EXPECT_EQ(frame->info, 0);
}

TEST(FalconFrame, ValuesLowNibbleFirst)
{
  // 0x1234 -> nibbles 4 3 2 1 -> "EDCB"; -1 = 0xffff -> "PPPP"; 1 -> "BAAA"; info 0x12 -> 'S'.
  FalconFrame frame;
  frame.values = {0x1234, -1, 1};
  frame.info = 0x12;
  const FalconFrameBytes bytes = encodeFalconFrame(frame);
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "<EDCBPPPPBAAASA>");
  std::string error;
  const auto decoded = decodeFalconFrame(bytesOf("<EDCBPPPPBAAASA>"), error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_EQ(decoded->values, frame.values);
  EXPECT_EQ(decoded->info, 0x12);
}

TEST(FalconFrame, EncoderFrameWithHomedAxesAndButtons)
{
  // Homed on all three axes (0x70) and button 1 (0x01): info 0x71, sent as 0x41 + 0x71 = 0xb2.
  auto bytes = bytesOf("<AAAAAAAAAAAAAA>");
  bytes[13] = 0xb2;
  std::string error;
  const auto frame = decodeFalconFrame(bytes, error);
  ASSERT_TRUE(frame) << error;
  EXPECT_EQ(frame->info & kFalconHomedAll, kFalconHomedAll);
  EXPECT_EQ(frame->info & kFalconButtonMask, 0x01);
}

TEST(FalconFrame, MalformedFramesAreRefused)
{
  std::string error;
  EXPECT_FALSE(decodeFalconFrame(bytesOf("<AAAAAAAAAAAAAA"), error));
  EXPECT_NE(error.find("16 bytes"), std::string::npos);
  EXPECT_FALSE(decodeFalconFrame(bytesOf("[AAAAAAAAAAAAAA>"), error));
  EXPECT_FALSE(decodeFalconFrame(bytesOf("<AAAAZAAAAAAAAA>"), error));
  EXPECT_NE(error.find("byte 5"), std::string::npos) << error;
  EXPECT_FALSE(decodeFalconFrame(bytesOf("<AAAAAAAAAAAA0A>"), error));
}

TEST(FalconFrameReader, FramesAcrossReadsNoiseAndCutFrames)
{
  FalconFrameReader reader;
  const std::string good = "<BAAACAAADAAAAA>";
  // Noise before the frame, then the frame in two pieces.
  EXPECT_FALSE(reader.push(bytesOf("xx" + good.substr(0, 7))));
  const auto frame = reader.push(bytesOf(good.substr(7)));
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->values, (std::array<std::int16_t, 3>{1, 2, 3}));
  EXPECT_EQ(reader.droppedBytes(), 2u);
  // A frame cut short by the next '<' is refused; the next one is taken.
  const auto next = reader.push(bytesOf("<AAAA" + std::string("<CAAAAAAAAAAAAA>")));
  ASSERT_TRUE(next);
  EXPECT_EQ(next->values[0], 2);
  EXPECT_EQ(reader.refusedFrames(), 1u);
  // Of two frames in one read, the newest wins; a bad one is counted.
  const auto newest = reader.push(bytesOf("<BAAAAAAAAAAAAA><AAAAAAAAAAAZAA><DAAAAAAAAAAAAA>"));
  ASSERT_TRUE(newest);
  EXPECT_EQ(newest->values[0], 3);
  EXPECT_EQ(reader.refusedFrames(), 2u);
}

} // namespace
} // namespace proxima
