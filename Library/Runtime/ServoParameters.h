// The servo's parameters (paper section 8): the spring, the force clamp and the safety rules of the
// force stage (ServoForce.h). Plain values, shared by the lockstep runner, the threaded runtime and
// the command line.
#pragma once

namespace proxima
{

/// The spring, force clamp and safety rules of the servo's force stage.
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
  /// After a scene change, or a start outside the object that holds the finger (ProxyStart.h),
  /// the force may change by at most this many newtons per second, for `sceneChangeWindow`
  /// seconds, so that a new model or a moved proxy does not kick the hand.
  double forceRateLimit = 200.0;
  /// Seconds after a scene change or a start outside during which `forceRateLimit` applies.
  double sceneChangeWindow = 0.1;
};

} // namespace proxima
