#include "Devices/ReplayDevice.h"

namespace proxima
{

ReplayDevice::ReplayDevice(std::vector<RecordedSample> samples, DeviceLimits limits)
  : m_samples(std::move(samples))
  , m_limits(limits)
{}

DeviceSample ReplayDevice::read(double time)
{
  // Times only go forward in a run: advance past every row not after `time`.
  while (m_next < m_samples.size() && m_samples[m_next].time <= time)
  {
    ++m_next;
  }
  if (m_next == 0)
  {
    // Before the first row: nothing recorded yet.
    DeviceSample sample;
    sample.valid = false;
    return sample;
  }
  const bool pastEnd = m_next == m_samples.size() && time > m_samples.back().time;
  DeviceSample sample = m_samples[m_next - 1].sample;
  if (pastEnd)
  {
    // The recording is over: the device is gone, as if unplugged.
    sample.valid = false;
    sample.connected = false;
  }
  return sample;
}

void ReplayDevice::writeForce(const Vec3& force, double /*time*/)
{
  m_lastForce = force;
}

RecordingDevice::RecordingDevice(HapticDevice& device, std::size_t expectedTicks)
  : m_device(device)
  , m_capacity(expectedTicks)
{
  m_samples.reserve(expectedTicks);
}

DeviceSample RecordingDevice::read(double time)
{
  const DeviceSample sample = m_device.read(time);
  // The servo thread calls this: within the reserved room only, so that it never allocates.
  if (m_samples.size() < m_capacity)
  {
    m_samples.push_back(RecordedSample{time, sample});
  }
  else
  {
    ++m_leftOut;
  }
  return sample;
}

} // namespace proxima
