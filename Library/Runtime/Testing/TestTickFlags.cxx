// Trace v2's flags column and back: setTickFlags undoes tickFlags for every bit and every pair of
// bits, so that a state rebuilt from a trace row or a remote run's stream writes the same row.
#include "Runtime/HapticState.h"

#include <gtest/gtest.h>

namespace proxima
{
namespace
{
TEST(TickFlags, SetTickFlagsUndoesTickFlags)
{
  constexpr int kBits = 11; // kTickBudgetLimited .. kTickStartedOutside
  for (int a = 0; a < kBits; ++a)
  {
    for (int b = a; b < kBits; ++b)
    {
      const std::uint32_t flags = (1u << a) | (1u << b);
      HapticState state;
      setTickFlags(state, flags);
      EXPECT_EQ(tickFlags(state), flags) << "bits " << a << " and " << b;
    }
  }
  HapticState all;
  setTickFlags(all, (1u << kBits) - 1u);
  EXPECT_TRUE(all.budgetLimited && all.hitIterationCap && all.forceClamped && all.fading &&
              all.deviceLost && all.fingerRefused && all.stuck && all.frictionLimited &&
              all.contactOverflow && all.rateLimited && all.startedOutside);
  setTickFlags(all, 0u);
  EXPECT_EQ(tickFlags(all), 0u);
}
} // namespace
} // namespace proxima
