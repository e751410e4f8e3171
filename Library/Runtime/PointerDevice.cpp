#include "Runtime/PointerDevice.h"

#include <algorithm>
#include <cmath>

namespace proxima
{

PointerDevice::PointerDevice(const PointerDeviceSettings& settings)
  : m_maxSpeed(settings.maxSpeed)
  , m_finger(settings.start)
{
  m_aim.write(Aim{settings.start, 0});
}

void PointerDevice::aimAt(const Vec3& target, std::uint32_t buttons)
{
  if (std::isfinite(target.x) && std::isfinite(target.y) && std::isfinite(target.z))
  {
    m_aim.write(Aim{target, buttons});
  }
}

Vec3 PointerDevice::aim() const
{
  return m_aim.read().target;
}

DeviceSample PointerDevice::read(double time)
{
  const Aim aim = m_aim.read();
  const double elapsed = m_read ? std::max(0.0, time - m_lastTime) : 0.0;
  m_read = true;
  m_lastTime = time;
  const Vec3 toAim = aim.target - m_finger;
  const double distance = norm(toAim);
  const double reach = m_maxSpeed * elapsed;
  m_finger = distance <= reach ? aim.target : m_finger + toAim * (reach / distance);
  DeviceSample sample;
  sample.position = m_finger;
  sample.buttons = aim.buttons;
  return sample;
}

void PointerDevice::writeForce(const Vec3& force, double /*time*/)
{
  m_lastForce.write(force);
}

} // namespace proxima
