// The lock-free snapshot: a reader racing a writer only ever sees values the writer wrote whole,
// in the order written. The writer fills every word of a 40-word value with the same counter, so
// a torn read shows as two different words.
#include "Runtime/SnapshotChannel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace proxima
{
namespace
{
struct WideValue
{
  std::uint64_t words[40];
};

TEST(SnapshotChannel, StartsAtTheDefaultValue)
{
  SnapshotChannel<WideValue> channel;
  const WideValue value = channel.read();
  for (const std::uint64_t word : value.words)
  {
    EXPECT_EQ(word, 0u);
  }
  EXPECT_EQ(channel.writes(), 1u);
}

TEST(SnapshotChannel, ConcurrentReadsAreNeverTornAndNeverGoBack)
{
  SnapshotChannel<WideValue> channel;
  constexpr std::uint64_t kWrites = 200000;
  std::atomic<bool> done{false};
  std::thread writer([&] {
    WideValue value{};
    for (std::uint64_t i = 1; i <= kWrites; ++i)
    {
      for (std::uint64_t& word : value.words)
      {
        word = i;
      }
      channel.write(value);
    }
    done.store(true);
  });
  std::uint64_t reads = 0;
  std::uint64_t torn = 0;
  std::uint64_t backwards = 0;
  std::uint64_t last = 0;
  while (!done.load() || reads == 0)
  {
    const WideValue value = channel.read();
    for (const std::uint64_t word : value.words)
    {
      torn += word != value.words[0] ? 1 : 0;
    }
    backwards += value.words[0] < last ? 1 : 0;
    last = value.words[0];
    ++reads;
  }
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(channel.read().words[39], kWrites);
  EXPECT_GT(reads, 0u);
}

} // namespace
} // namespace proxima
