// Lockstep mode: the haptic tick (HapticStep.h) run in one thread on a virtual clock. The same
// input gives the same trace bit for bit (all but the measured solve time), so scripted runs are
// testable. Where a lockstep tick begins: runLockstep -> hapticStep -> ProxySolver::update and
// ServoForce::step.
#pragma once

#include "Proxy/ProxySolver.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticDevice.h"
#include "Runtime/HapticState.h"
#include "Runtime/ServoParameters.h"
#include "Runtime/TickDynamics.h"

#include <cstdint>
#include <functional>

namespace proxima
{

/// Which ticks a lockstep run plays, on its virtual clock.
struct LockstepSettings
{
  /// Servo rate in Hz: tick k runs at startTime + k / rate.
  double rate = 1000.0;
  /// Time of tick 0 in seconds on the virtual clock (a path's first sample for lockstepCovering).
  double startTime = 0.0;
  /// Number of ticks to run, 0, 1, ... numTicks - 1.
  std::uint64_t numTicks = 0;
};

/// Number of servo ticks that cover [start, end] at `rate` (both ends included).
std::uint64_t ticksCovering(double start, double end, double rate);

/// The lockstep run that plays all of `path` at `rate`: from its first sample to its last.
LockstepSettings lockstepCovering(const FingerPath& path, double rate);

/// Runs settings.numTicks ticks and hands each tick's state to `onTick`, in order; with
/// `dynamics`, each tick ends with its bodies' step.
void runLockstep(const LockstepSettings& settings, ProxySolver& solver, HapticDevice& device,
                 const ServoParameters& parameters,
                 const std::function<void(const HapticState&)>& onTick,
                 TickDynamics* dynamics = nullptr);

} // namespace proxima
