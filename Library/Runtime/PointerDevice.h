// The finger of a person without a haptic device: a mouse (or any pointer) aims it, the window's
// thread says where it should go (aimAt), and the servo thread's reads move it there no faster
// than a hand moves, so a flick across the screen does not teleport the finger through an organ.
// It has no motors: the force it is given is kept for display only. The aim is handed between the
// threads through a SnapshotChannel: no lock, and the servo thread never waits.
//
// In the Runtime layer beside SimulatedDevice, not in Devices: it needs no hardware library, and
// the VTK layer, which aims it from mouse events (vtkHapticMouseFinger), should not link hidapi
// and libusb for it.
#pragma once

#include "Runtime/HapticDevice.h"
#include "Runtime/SnapshotChannel.h"

#include <atomic>
#include <cstdint>

namespace proxima
{

/// Where a PointerDevice's finger starts and how fast it may move.
struct PointerDeviceSettings
{
  /// Where the finger is before the first aim (the world's workspace centre).
  Vec3 start;
  /// The finger's top speed in m/s. A hand probing tissue moves at 0.05-0.5 m/s and jabs at up to
  /// a few m/s (the probe paths' figures); 0.5 m/s lets a person press and stroke at will while a
  /// pointer's jump of 10 cm takes 0.2 s, which the proxy follows along the surface.
  double maxSpeed = 0.5;
};

/// A finger aimed by a mouse or other pointer from one thread and read by the servo thread, moving
/// toward the aim no faster than `maxSpeed`. Renders no force.
class PointerDevice final : public HapticDevice
{
public:
  /// A finger at `settings.start`, aimed there until the first aimAt.
  explicit PointerDevice(const PointerDeviceSettings& settings);

  /// Any one thread (the window's): where the finger should go, and the buttons held.
  void aimAt(const Vec3& target, std::uint32_t buttons = 0);
  /// The last aim given (the start before any).
  Vec3 aim() const;

  /// The servo thread: the finger moved toward the aim by at most maxSpeed times the time since
  /// the last read (nothing on the first read, or if the clock went back).
  DeviceSample read(double time) override;
  /// Keeps `force` for lastForce(); the pointer has no motors to render it.
  void writeForce(const Vec3& force, double time) override;
  const char* name() const override { return "mouse"; }

  /// The last force written, for display (any thread).
  Vec3 lastForce() const { return m_lastForce.read(); }
  /// The finger's top speed in m/s, from the settings.
  double maxSpeed() const { return m_maxSpeed; }

private:
  struct Aim
  {
    Vec3 target;
    std::uint32_t buttons = 0;
  };

  SnapshotChannel<Aim> m_aim;
  SnapshotChannel<Vec3> m_lastForce;
  const double m_maxSpeed;
  // The servo thread's own.
  Vec3 m_finger;
  double m_lastTime = 0.0;
  bool m_read = false;
};

} // namespace proxima
