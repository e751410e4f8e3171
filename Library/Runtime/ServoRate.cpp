#include "Runtime/ServoRate.h"

#include <cstdio>

namespace proxima
{

std::string servoRateRange()
{
  char text[64];
  std::snprintf(text, sizeof text, "from %g to %g Hz", kMinServoRate, kMaxServoRate);
  return text;
}

std::string servoRateError(double rate)
{
  if (isServoRate(rate))
  {
    return {};
  }
  char value[64];
  std::snprintf(value, sizeof value, "%g", rate);
  return std::string("servo rate ") + value + " Hz: must be " + servoRateRange();
}

} // namespace proxima
