// Playing back and recording device sessions. ReplayDevice answers each read with the recorded
// sample of the latest time not after it (the recorded run's own tick times match exactly), and
// reports a disconnect after the recording ends. RecordingDevice wraps any device and keeps what
// it read, for writeDeviceRecording at the end (kept in memory, so the servo tick does no I/O, in
// room reserved up front, so it does not allocate either: reads past it are counted, not kept).
#pragma once

#include "Devices/DeviceRecording.h"

#include <vector>

namespace proxima
{

/// A device that plays a recording back: each read gives the sample recorded at the latest time
/// not after it, an invalid sample before the first row, and a lost device after the last.
class ReplayDevice final : public HapticDevice
{
public:
  /// Plays `samples` back (times never decreasing, as readDeviceRecording gives them);
  /// `limits` is what limits() reports, unbounded by default.
  explicit ReplayDevice(std::vector<RecordedSample> samples, DeviceLimits limits = DeviceLimits{});

  DeviceSample read(double time) override;
  void writeForce(const Vec3& force, double time) override;
  DeviceLimits limits() const override { return m_limits; }
  const char* name() const override { return "replay"; }

  /// The recording being played back.
  const std::vector<RecordedSample>& samples() const { return m_samples; }
  /// The force (N) of the latest writeForce(), which a replay only keeps; zero before any.
  const Vec3& lastForce() const { return m_lastForce; }

private:
  std::vector<RecordedSample> m_samples;
  DeviceLimits m_limits;
  std::size_t m_next = 0;
  Vec3 m_lastForce;
};

/// Wraps a device and records every sample it reads, for writeDeviceRecording() after the run;
/// forces, limits and name pass through to the wrapped device.
class RecordingDevice final : public HapticDevice
{
public:
  /// `device` must outlive this; room for `expectedTicks` samples is reserved up front, and only
  /// that many are kept.
  RecordingDevice(HapticDevice& device, std::size_t expectedTicks);

  DeviceSample read(double time) override;
  void writeForce(const Vec3& force, double time) override { m_device.writeForce(force, time); }
  DeviceLimits limits() const override { return m_device.limits(); }
  const char* name() const override { return m_device.name(); }

  /// The samples recorded so far, in the order they were read; read them once the run is over,
  /// since the servo thread appends to them.
  const std::vector<RecordedSample>& samples() const { return m_samples; }
  /// Reads past the reserved room: passed on, not recorded.
  std::size_t samplesLeftOut() const { return m_leftOut; }

private:
  HapticDevice& m_device;
  std::vector<RecordedSample> m_samples;
  std::size_t m_capacity = 0;
  std::size_t m_leftOut = 0;
};

} // namespace proxima
