// The one rule for the servo rate of the real-time loops (paper section 8: a fixed rate of at
// least 1 kHz; 10 kHz is the most a deadline loop on a desktop kernel keeps). The threaded runtime,
// vtkHapticRenderer and the command line all check a rate here, at configuration time, and refuse
// one outside the range instead of clamping it: a clamped rate ran the loop at one rate while the
// proxy's time step (viscous friction, eq. 21) was derived from another.
#pragma once

#include <string>

namespace proxima
{

/// The slowest real-time servo loop (Hz): the paper's fixed rate of at least 1 kHz.
inline constexpr double kMinServoRate = 1000.0;
/// The fastest real-time servo loop (Hz): the most a deadline loop on a desktop kernel keeps.
inline constexpr double kMaxServoRate = 10000.0;

/// True when the real-time servo loop can run at `rate` Hz (NaN is not a rate).
inline bool isServoRate(double rate)
{
  return rate >= kMinServoRate && rate <= kMaxServoRate;
}

/// The rule in words, for messages: "from 1000 to 10000 Hz".
std::string servoRateRange();

/// Empty when `rate` is a servo rate; otherwise a one-line reason that names the value and the
/// range.
std::string servoRateError(double rate);

} // namespace proxima
