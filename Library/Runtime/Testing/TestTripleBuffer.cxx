// The triple buffer that hands a deforming surface to a drawing thread: a reader racing a writer
// only ever takes values the writer published whole, newer each time, and the last one written
// once the writer stops. The writer fills every element of a vector with the same counter, so a
// value read while the writer was filling it shows as two different elements. (ThreadSanitizer
// runs this too: a buffer touched by both sides at once is a race it reports.)
#include "Runtime/TripleBuffer.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace proxima
{
namespace
{
TEST(TripleBuffer, TakesNothingUntilAPublishAndThenTheNewestOnce)
{
  TripleBuffer<std::vector<int>> buffer(std::vector<int>(3, 7));
  EXPECT_FALSE(buffer.take());
  EXPECT_EQ(buffer.front(), std::vector<int>(3, 7)); // the initial value
  for (int value = 1; value <= 3; ++value)
  {
    buffer.back().assign(3, value);
    buffer.publish();
  }
  ASSERT_TRUE(buffer.take());
  EXPECT_EQ(buffer.front(), std::vector<int>(3, 3)); // 1 and 2 were skipped, never queued
  EXPECT_FALSE(buffer.take());
  EXPECT_EQ(buffer.front(), std::vector<int>(3, 3));
  buffer.back().assign(3, 4);
  buffer.publish();
  ASSERT_TRUE(buffer.take());
  EXPECT_EQ(buffer.front(), std::vector<int>(3, 4));
}

TEST(TripleBuffer, ConcurrentTakesAreNeverTornAndNeverGoBack)
{
  constexpr std::uint64_t kWrites = 100000;
  TripleBuffer<std::vector<std::uint64_t>> buffer(std::vector<std::uint64_t>(64, 0));
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (std::uint64_t i = 1; i <= kWrites; ++i)
    {
      std::vector<std::uint64_t>& back = buffer.back();
      ASSERT_EQ(back.size(), 64u); // the room it was given: filled in place, never grown
      for (std::uint64_t& element : back)
      {
        element = i;
      }
      buffer.publish();
    }
    done.store(true);
  });
  std::uint64_t takes = 0;
  std::uint64_t torn = 0;
  std::uint64_t backwards = 0;
  std::uint64_t last = 0;
  while (!done.load())
  {
    if (!buffer.take())
    {
      continue;
    }
    const std::vector<std::uint64_t>& value = buffer.front();
    for (const std::uint64_t element : value)
    {
      torn += element != value[0] ? 1 : 0;
    }
    backwards += value[0] <= last ? 1 : 0;
    last = value[0];
    ++takes;
  }
  writer.join();
  // The writer's last value is there to take once it stops, unless it was taken already.
  if (buffer.take())
  {
    ++takes;
  }
  EXPECT_EQ(buffer.front()[63], kWrites);
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_GT(takes, 0u);
}

} // namespace
} // namespace proxima
