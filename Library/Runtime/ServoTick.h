// One servo tick, the step function shared by the lockstep runner and the threaded runtime:
// read the device, update the proxy, compute the spring force, write it to the device.
#pragma once

#include "Proxy/ProxySolver.h"
#include "Runtime/HapticDevice.h"

#include <cstdint>

namespace proxima
{

struct ServoParameters
{
  /// Spring stiffness kp in N/m: force on the finger = kp (proxy - finger).
  double stiffness = 1000.0;
  /// Forces are clamped to this magnitude (the device's limit), in newtons.
  double maxForce = 10.0;
  /// Watchdog: a proxy state older than this (seconds) means the proxy loop stalled, and the
  /// force fades out. Only the threaded runtime has stale states.
  double watchdogTimeout = 0.005;
  /// Time in seconds over which the force fades to zero (stall, device lost).
  double fadeTime = 0.05;
  /// After a scene change, the force may change by at most this many newtons per second, for
  /// `sceneChangeWindow` seconds, so that a new model does not kick the hand.
  double forceRateLimit = 200.0;
  double sceneChangeWindow = 0.1;
};

/// What one tick did: the rows of the trace file (DESIGN.md section 3).
struct TickRecord
{
  std::uint64_t tick = 0;
  double time = 0.0;
  Vec3 finger;
  Vec3 proxy;
  Vec3 force;
  int contacts = 0;
  int iterations = 0;
  /// Wall time of the proxy update in nanoseconds: the one field that is not deterministic.
  std::int64_t solveNanoseconds = 0;
  bool fingerRefused = false;
  bool hitIterationCap = false;
  bool contactOverflow = false;
  bool forceClamped = false;
  /// Static friction held the proxy; dynamic or viscous friction shortened its slide.
  bool stuck = false;
  bool frictionLimited = false;
  std::uint32_t trianglesTested = 0;
};

/// Runs one tick at `time`. `lastForce` is the force of the previous tick, held when the finger
/// sample is invalid or not finite; it is updated on return.
TickRecord runServoTick(std::uint64_t tick, double time, ProxySolver& solver, HapticDevice& device,
                        const ServoParameters& parameters, Vec3& lastForce);

} // namespace proxima
