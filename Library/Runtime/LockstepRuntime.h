// Lockstep mode: the servo tick run in one thread on a virtual clock. The same input gives the
// same trace bit for bit (all but the measured solve time), so scripted runs are testable.
#pragma once

#include "Runtime/ServoTick.h"

#include <cstdint>
#include <functional>

namespace proxima
{

struct LockstepSettings
{
  /// Servo rate in Hz: tick k runs at startTime + k / rate.
  double rate = 1000.0;
  double startTime = 0.0;
  std::uint64_t numTicks = 0;
};

/// Number of servo ticks that cover [start, end] at `rate` (both ends included).
std::uint64_t ticksCovering(double start, double end, double rate);

/// Runs settings.numTicks ticks and hands each record to `onTick`, in order.
void runLockstep(const LockstepSettings& settings, ProxySolver& solver, HapticDevice& device,
                 const ServoParameters& parameters,
                 const std::function<void(const TickRecord&)>& onTick);

} // namespace proxima
