// The conditions of a tick: their bits are trace v2's flags values, the names table lists each
// once, and a bitmask read back from a trace row or a message holds the conditions it was made of.
#include "Core/TickConditions.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <type_traits>

namespace proxima
{
namespace
{
static_assert(std::is_trivially_copyable_v<TickConditions> &&
                sizeof(TickConditions) == sizeof(std::uint32_t),
              "a state holding the conditions is copied between threads word by word");

TEST(TickConditions, BitsAreTheTraceFormatsFlagValues)
{
  // Documentation/CommandLine.md's table: these values are in every trace written.
  EXPECT_EQ(TickConditions(TickCondition::budgetLimited).bits(), 1u);
  EXPECT_EQ(TickConditions(TickCondition::hitIterationCap).bits(), 2u);
  EXPECT_EQ(TickConditions(TickCondition::forceClamped).bits(), 4u);
  EXPECT_EQ(TickConditions(TickCondition::forceFading).bits(), 8u);
  EXPECT_EQ(TickConditions(TickCondition::deviceLost).bits(), 16u);
  EXPECT_EQ(TickConditions(TickCondition::fingerRefused).bits(), 32u);
  EXPECT_EQ(TickConditions(TickCondition::stuck).bits(), 64u);
  EXPECT_EQ(TickConditions(TickCondition::frictionLimited).bits(), 128u);
  EXPECT_EQ(TickConditions(TickCondition::contactOverflow).bits(), 256u);
  EXPECT_EQ(TickConditions(TickCondition::forceRateLimited).bits(), 512u);
  EXPECT_EQ(TickConditions(TickCondition::startedOutside).bits(), 1024u);
  EXPECT_EQ(TickConditions(TickCondition::pushedByObject).bits(), 2048u);
  EXPECT_EQ(TickConditions(TickCondition::surfaceLagging).bits(), 4096u);
}

TEST(TickConditions, TheNamesTableListsEveryBitOnceInOrder)
{
  std::set<std::string> names;
  std::uint32_t expected = 1u;
  for (const TickConditionName& entry : kTickConditionNames)
  {
    EXPECT_EQ(static_cast<std::uint32_t>(entry.condition), expected) << entry.name;
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name << " twice";
    EXPECT_EQ(std::string(tickConditionName(entry.condition)), entry.name);
    expected <<= 1;
  }
  EXPECT_EQ(names.size(), 13u);
  // A value that is no single condition has no name.
  EXPECT_EQ(std::string(tickConditionName(static_cast<TickCondition>(3u))), "");
}

TEST(TickConditions, BitsReadBackHoldTheSameConditions)
{
  constexpr int kBits = sizeof(kTickConditionNames) / sizeof(kTickConditionNames[0]);
  for (int a = 0; a < kBits; ++a)
  {
    for (int b = a; b < kBits; ++b)
    {
      TickConditions conditions;
      conditions.set(kTickConditionNames[a].condition);
      conditions.set(kTickConditionNames[b].condition);
      const TickConditions read(conditions.bits());
      EXPECT_EQ(read, conditions) << "bits " << a << " and " << b;
      for (int c = 0; c < kBits; ++c)
      {
        EXPECT_EQ(read.has(kTickConditionNames[c].condition), c == a || c == b)
          << "bits " << a << " and " << b << ", asked " << c;
      }
    }
  }
}

TEST(TickConditions, SetClearsWhenNotMet)
{
  TickConditions conditions(TickCondition::stuck | TickCondition::forceFading);
  conditions.set(TickCondition::stuck, false);
  EXPECT_FALSE(conditions.has(TickCondition::stuck));
  EXPECT_TRUE(conditions.has(TickCondition::forceFading));
  conditions.clear(TickCondition::forceFading);
  EXPECT_TRUE(conditions.none());
  const TickConditions all = TickConditions(0xfffu);
  EXPECT_EQ(all.without(TickCondition::budgetLimited | TickCondition::pushedByObject).bits(),
            0xfffu & ~(1u | 2048u));
  EXPECT_TRUE(all.hasAny(TickCondition::deviceLost));
  EXPECT_FALSE(TickConditions().hasAny(TickCondition::deviceLost | TickCondition::stuck));
}
} // namespace
} // namespace proxima
