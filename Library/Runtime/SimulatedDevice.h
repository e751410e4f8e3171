// A device that plays a scripted finger path and keeps the last force it was given: the input of
// every scripted run and test.
#pragma once

#include "Runtime/FingerPath.h"
#include "Runtime/HapticDevice.h"

namespace proxima
{

/// A device that plays a FingerPath: each read is the path's position at the tick's time, and each
/// force written is kept. For one thread (the servo's, or the lockstep runner's).
class SimulatedDevice final : public HapticDevice
{
public:
  /// A device that plays `path` (times on the runtime's clock).
  explicit SimulatedDevice(FingerPath path)
    : m_path(std::move(path))
  {}

  /// The path's position at `time`, interpolated and held beyond its ends; always valid.
  DeviceSample read(double time) override
  {
    return DeviceSample{m_path.positionAt(time, m_hint), true};
  }
  void writeForce(const Vec3& force, double /*time*/) override { m_lastForce = force; }
  const char* name() const override { return "sim"; }

  /// The path the device plays.
  const FingerPath& path() const { return m_path; }
  /// The last force written (N, on the finger); zero before any.
  const Vec3& lastForce() const { return m_lastForce; }

private:
  FingerPath m_path;
  std::size_t m_hint = 0;
  Vec3 m_lastForce;
};

} // namespace proxima
