// The device interface of the runtime, in SI units: where the finger is, and the force to apply.
// Virtual by design: it sits at the servo loop's edge, outside the proxy update. Errors are
// values: a sample says whether it holds a position and whether the device is still there; no
// call throws. `read` is the device's deterministic step: a device driven by a recording or an
// emulator gives the same samples for the same sequence of times.
#pragma once

#include "Core/Aabb.h"
#include "Core/Vec3.h"

#include <array>
#include <cstdint>
#include <limits>

namespace proxima
{

/// What a device reports for one tick: the finger's position, whether the reading holds, and
/// its buttons and orientation.
struct DeviceSample
{
  /// Finger (end-effector) position in metres, world frame.
  Vec3 position;
  /// False when the device had nothing to report this tick (a short or malformed read): the tick
  /// holds the last force.
  bool valid = true;
  /// False once the device is gone (unplugged, transport closed). The servo loop fades the force
  /// out and reports the loss; `valid` is false too.
  bool connected = true;
  /// Button states, bit i for button i.
  std::uint32_t buttons = 0;
  /// True when the device reports an orientation (`orientation` holds it).
  bool hasOrientation = false;
  /// Orientation as a unit quaternion (w, x, y, z); meaningful only when `hasOrientation`.
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};
};

/// What a device can reach and push. An empty workspace means unbounded.
struct DeviceLimits
{
  /// The box the finger can reach, metres, world frame.
  Aabb workspace;
  /// Largest force magnitude in newtons the device can render.
  double maxForce = std::numeric_limits<double>::infinity();
};

/// A haptic device as the servo loop sees it: read the finger, write the force, once per tick.
/// Implementations report errors in the samples and do not throw.
class HapticDevice
{
public:
  virtual ~HapticDevice() = default;
  /// Reads the finger position for the tick at `time` (seconds on the runtime's clock).
  virtual DeviceSample read(double time) = 0;
  /// Commands `force` (newtons, on the finger) for the tick at `time`.
  virtual void writeForce(const Vec3& force, double time) = 0;
  /// The device's workspace and force limit; the servo clamps to the smaller of this and its own.
  virtual DeviceLimits limits() const { return DeviceLimits{}; }
  /// The device's kind as `proxima run --device` names it (sim, replay, spacemouse, falcon).
  virtual const char* name() const { return "device"; }
};

} // namespace proxima
