// The one servo-rate rule (ServoRate.h): 1 to 10 kHz, both ends included; anything else, NaN and
// infinities among it, is refused with a message that names the value and the range.
#include "Runtime/ServoRate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace proxima
{
namespace
{

TEST(ServoRate, AcceptsTheRangeWithBothEnds)
{
  for (const double rate : {1000.0, 2000.0, 4000.0, 9999.5, 10000.0})
  {
    EXPECT_TRUE(isServoRate(rate)) << rate;
    EXPECT_EQ(servoRateError(rate), "") << rate;
  }
}

TEST(ServoRate, RefusesEverythingElse)
{
  const double infinity = std::numeric_limits<double>::infinity();
  for (const double rate :
       {999.999, 1.0, 0.0, -1000.0, 10000.001, 20000.0, infinity, -infinity, std::nan("")})
  {
    EXPECT_FALSE(isServoRate(rate)) << rate;
    EXPECT_FALSE(servoRateError(rate).empty()) << rate;
  }
}

TEST(ServoRate, TheMessageNamesTheValueAndTheRange)
{
  EXPECT_EQ(servoRateRange(), "from 1000 to 10000 Hz");
  EXPECT_EQ(servoRateError(500.0), "servo rate 500 Hz: must be from 1000 to 10000 Hz");
  EXPECT_EQ(servoRateError(20000.0), "servo rate 20000 Hz: must be from 1000 to 10000 Hz");
}

} // namespace
} // namespace proxima
