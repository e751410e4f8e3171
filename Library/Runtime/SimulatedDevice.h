// A device that plays a scripted finger path and keeps the last force it was given: the input of
// every scripted run and test.
#pragma once

#include "Runtime/FingerPath.h"
#include "Runtime/HapticDevice.h"

namespace proxima
{

class SimulatedDevice final : public HapticDevice
{
public:
  explicit SimulatedDevice(FingerPath path)
    : m_path(std::move(path))
  {}

  DeviceSample read(double time) override
  {
    return DeviceSample{m_path.positionAt(time, m_hint), true};
  }
  void writeForce(const Vec3& force, double /*time*/) override { m_lastForce = force; }
  const char* name() const override { return "sim"; }

  const FingerPath& path() const { return m_path; }
  const Vec3& lastForce() const { return m_lastForce; }

private:
  FingerPath m_path;
  std::size_t m_hint = 0;
  Vec3 m_lastForce;
};

} // namespace proxima
