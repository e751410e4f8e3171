// The servo-to-reader state stream: states come out in the order pushed, whole, and a full ring
// drops (and counts) what it cannot hold rather than waiting; with a reader on another thread,
// every state pushed is either drained exactly once or counted dropped.
#include "Runtime/StateStream.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>
#include <vector>

namespace proxima
{
namespace
{
struct Wide
{
  std::uint64_t words[40];
};

Wide wide(std::uint64_t value)
{
  Wide w;
  for (std::uint64_t& word : w.words)
  {
    word = value;
  }
  return w;
}

TEST(StateStream, DrainsInOrderAndDropsWhenFull)
{
  StateStream<Wide> stream(3);
  std::vector<Wide> out;
  EXPECT_EQ(stream.drain(out), 0u);
  EXPECT_TRUE(stream.push(wide(1)));
  EXPECT_TRUE(stream.push(wide(2)));
  EXPECT_TRUE(stream.push(wide(3)));
  EXPECT_FALSE(stream.push(wide(4)));
  EXPECT_EQ(stream.dropped(), 1u);
  ASSERT_EQ(stream.drain(out), 3u);
  EXPECT_EQ(out[0].words[0], 1u);
  EXPECT_EQ(out[1].words[0], 2u);
  EXPECT_EQ(out[2].words[0], 3u);
  // Drained slots are free again, and the ring wraps.
  for (std::uint64_t v = 5; v < 12; ++v)
  {
    EXPECT_TRUE(stream.push(wide(v)));
    ASSERT_EQ(stream.drain(out), 1u);
    EXPECT_EQ(out.back().words[39], v);
  }
  EXPECT_EQ(stream.dropped(), 1u);
}

TEST(StateStream, EveryStateIsDrainedOnceOrCountedDroppedAcrossThreads)
{
  constexpr std::uint64_t kPushes = 100000;
  StateStream<Wide> stream(64);
  std::uint64_t accepted = 0;
  std::thread producer([&] {
    for (std::uint64_t v = 1; v <= kPushes; ++v)
    {
      accepted += stream.push(wide(v)) ? 1 : 0;
    }
  });
  std::vector<Wide> out;
  std::uint64_t last = 0;
  std::uint64_t received = 0;
  bool torn = false;
  bool outOfOrder = false;
  auto take = [&] {
    out.clear();
    stream.drain(out);
    for (const Wide& w : out)
    {
      for (const std::uint64_t word : w.words)
      {
        torn = torn || word != w.words[0];
      }
      outOfOrder = outOfOrder || w.words[0] <= last;
      last = w.words[0];
      ++received;
    }
  };
  while (received + stream.dropped() < kPushes)
  {
    take();
  }
  producer.join();
  take();
  EXPECT_FALSE(torn);
  EXPECT_FALSE(outOfOrder);
  EXPECT_EQ(received, accepted);
  EXPECT_EQ(received + stream.dropped(), kPushes);
}

} // namespace
} // namespace proxima
