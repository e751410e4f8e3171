// TriangleTestCache against std::unordered_set: the cache may forget (when full it answers "not
// tested yet", which only costs a second exact test) but must never claim a triangle was tested
// when it was not since the last clear, because the query would then skip that triangle.
#include "Geometry/TriangleTestCache.h"

#include "GeometryTestSupport.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <unordered_set>

namespace proxima::test
{
namespace
{

TEST(TriangleTestCache, InsertReportsFirstTimeOnlyUntilCleared)
{
  auto cache = std::make_unique<TriangleTestCache>();
  cache->clear();
  EXPECT_TRUE(cache->insert(7));
  EXPECT_FALSE(cache->insert(7));
  EXPECT_TRUE(cache->insert(8));
  EXPECT_FALSE(cache->insert(7));
  cache->clear();
  EXPECT_TRUE(cache->insert(7));
  EXPECT_TRUE(cache->insert(8));
  // Without any clear, a fresh cache is already empty.
  auto fresh = std::make_unique<TriangleTestCache>();
  EXPECT_TRUE(fresh->insert(0));
  EXPECT_FALSE(fresh->insert(0));
}

TEST(TriangleTestCache, MatchesASetOnRandomQueries)
{
  constexpr std::uint64_t kSeed = 0xcac4e001;
  Random random(kSeed);
  auto cache = std::make_unique<TriangleTestCache>();
  std::unordered_set<std::uint32_t> reference;
  FailureBudget budget;
  int numFailures = 0;
  long numOperations = 0;
  for (int query = 0; query < 10000; ++query)
  {
    cache->clear();
    reference.clear();
    // Ids in a narrow range repeat often; ids a multiple of kSlots apart share a home slot and
    // exercise the probing; some queries run past capacity.
    const int numInserts = random.integer(1, random.chance(0.1) ? 1500 : 200);
    const std::uint32_t base = static_cast<std::uint32_t>(random.integer(0, 1 << 30));
    for (int i = 0; i < numInserts; ++i)
    {
      std::uint32_t id = base + static_cast<std::uint32_t>(random.integer(0, 300));
      if (random.chance(0.3))
      {
        id = base + TriangleTestCache::kSlots * static_cast<std::uint32_t>(random.integer(0, 40));
      }
      const bool full = reference.size() >= TriangleTestCache::kMaxEntries;
      const bool known = reference.count(id) > 0;
      const bool answer = cache->insert(id);
      ++numOperations;
      // Below capacity the answer is exact; at capacity "not tested" is always allowed.
      const bool ok = full ? (answer || known) : answer == !known;
      if (!ok && budget.spend())
      {
        ADD_FAILURE() << "seed 0x" << std::hex << kSeed << std::dec << " query " << query
                      << " insert " << i << " id " << id << ": answered " << answer << " with "
                      << reference.size() << " distinct ids known, id known " << known;
      }
      numFailures += ok ? 0 : 1;
      if (!full)
      {
        reference.insert(id);
      }
    }
  }
  EXPECT_EQ(numFailures, 0) << "of " << numOperations << " inserts";
}

TEST(TriangleTestCache, WhenFullEveryTriangleIsTestedAgain)
{
  auto cache = std::make_unique<TriangleTestCache>();
  cache->clear();
  for (std::uint32_t i = 0; i < TriangleTestCache::kMaxEntries; ++i)
  {
    ASSERT_TRUE(cache->insert(i * 3u));
  }
  // Full: new ids and old ones alike are reported untested (correct, only slower).
  EXPECT_TRUE(cache->insert(999999));
  EXPECT_TRUE(cache->insert(999999));
  EXPECT_TRUE(cache->insert(0));
  // A clear makes it exact again.
  cache->clear();
  EXPECT_TRUE(cache->insert(0));
  EXPECT_FALSE(cache->insert(0));
}

TEST(TriangleTestCache, GenerationWrapForgetsOldEntries)
{
  // An entry left in a slot by generation 1 must not match when the 32-bit generation counter
  // comes round to 1 again. A fresh cache starts at generation 1, so after 2^32 clears the
  // counter has wrapped and is back at 1 (or past it, if the wrap skips 0). About two seconds of
  // increments: there is no other way to the wrap through the public interface.
  auto cache = std::make_unique<TriangleTestCache>();
  ASSERT_TRUE(cache->insert(42));
  ASSERT_FALSE(cache->insert(42));
  for (std::uint64_t i = 0; i < 0x100000000ull; ++i)
  {
    cache->clear();
  }
  EXPECT_TRUE(cache->insert(42)) << "a stale entry from before the wrap matched";
  EXPECT_FALSE(cache->insert(42));
  EXPECT_TRUE(cache->insert(43));
}

} // namespace
} // namespace proxima::test
