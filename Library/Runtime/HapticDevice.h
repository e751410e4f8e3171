// The device interface of the runtime, in SI units: where the finger is, and the force to apply.
// Virtual by design: it sits at the servo loop's edge, outside the proxy update.
#pragma once

#include "Core/Vec3.h"

namespace proxima
{

struct DeviceSample
{
  /// Finger (end-effector) position in metres, world frame.
  Vec3 position;
  /// False when the device had nothing to report this tick (disconnect, read error).
  bool valid = true;
};

class HapticDevice
{
public:
  virtual ~HapticDevice() = default;
  /// Reads the finger position for the tick at `time` (seconds on the runtime's clock).
  virtual DeviceSample read(double time) = 0;
  /// Commands `force` (newtons, on the finger) for the tick at `time`.
  virtual void writeForce(const Vec3& force, double time) = 0;
};

} // namespace proxima
