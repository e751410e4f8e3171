// What one haptic tick starts from: its number and time on the runtime's clock, and the device's
// sample at that time. The input of the tick's step (HapticStep.h) in every runner, and what the
// threaded runtime's servo thread posts to its proxy thread.
#pragma once

#include "Runtime/HapticDevice.h"

#include <cstdint>

namespace proxima
{

struct TickInput
{
  /// Servo tick number: tick k of a run at rate f runs at startTime + k / f.
  std::uint64_t tick = 0;
  /// Seconds on the runtime's clock (virtual in lockstep, the servo clock's when threaded).
  double time = 0.0;
  /// The finger and the device's state (valid, connected, buttons) at `time`.
  DeviceSample sample;
};

} // namespace proxima
