// The small public way in (Documentation/Library.md): one scene, its proxy solver and the servo's
// force stage, for a program that moves a finger itself (a script, a device loop of its own, a
// test) and wants the proxy and the force the device would render. `run` plays a whole path in
// lockstep exactly as `proxima run` does (the same trace, bit for bit, but the solve times);
// `step` is one tick at a time on the same virtual clock. Kernel only: plain C++, no
// third-party package. Not for the haptic threads themselves (the threaded runtime is,
// ThreadedRuntime.h): placing the proxy allocates.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Proxy/ProxyParameters.h"
#include "Proxy/ProxySolver.h"
#include "Proxy/ProxyStart.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticState.h"
#include "Runtime/ServoForce.h"
#include "Runtime/ServoParameters.h"
#include "Runtime/TickDynamics.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace proxima
{

/// What a HapticSession runs with: the proxy's parameters, the servo's and the servo rate.
struct HapticSessionSettings
{
  /// The proxy: radius (metres), skin, iteration cap and work budget (ProxyParameters.h). Its
  /// stiffness and time step are the servo's and the rate's: the session sets them.
  ProxyParameters proxy;
  /// The spring kp (N/m), the force clamp (N) and the force stage's safety rules.
  ServoParameters servo;
  /// Servo rate in Hz: tick k runs at the path's start + k / rate.
  double rate = 1000.0;
};

/// One scene, its proxy solver and the servo's force stage, stepped by the caller on a virtual
/// clock. For one thread; not real-time safe (placing the proxy allocates).
class HapticSession
{
public:
  /// A session on `scene`, which it shares (and keeps alive) for as long as it lives. The proxy is
  /// placed at the first finger it is given (placeProxy, step or run).
  explicit HapticSession(std::shared_ptr<const CollisionScene> scene,
                         const HapticSessionSettings& settings = {});
  ~HapticSession();
  HapticSession(const HapticSession&) = delete;
  HapticSession& operator=(const HapticSession&) = delete;

  /// Places the proxy for a finger at `finger`: there, or, when `finger` is inside a closed object
  /// of the scene, at the nearest free point outside it (ProxyStart.h; the next tick reports it
  /// and the force ramps in). Restarts the clock and the force stage.
  const ProxyStartPlacement& placeProxy(const Vec3& finger);
  /// The scene's bodies (paper section 6), stepped at the end of every tick from now on with the
  /// tick's force (Runtime/TickDynamics.h): their objects move in the solver. The session keeps
  /// them; they are not reset when the proxy is placed again (a second `run` continues where the
  /// bodies are), and placing the proxy checks the objects where the scene placed them.
  void setDynamics(std::shared_ptr<TickDynamics> dynamics);
  /// The bodies set by setDynamics(), or null when the scene has none.
  const TickDynamics* dynamics() const { return m_dynamics.get(); }
  /// One tick with the finger at `finger`: the proxy's update toward it and the force on the
  /// device, kp (proxy - finger) clamped to the servo's limit. The first tick places the proxy.
  HapticState step(const Vec3& finger);
  /// The whole of `path` in lockstep at the session's rate, placing the proxy at its first
  /// sample: one state per tick, as `proxima run` writes them to its trace.
  std::vector<HapticState> run(const FingerPath& path);

  /// Where the proxy is now (metres, world frame): after the last tick or placement.
  const Vec3& proxy() const { return m_solver->proxy(); }
  /// Where the proxy was last placed, and whether it had to move out of an object.
  const ProxyStartPlacement& placement() const { return m_placement; }
  /// The settings in use: those given, with the proxy's stiffness and time step set from the
  /// servo's kp and the rate.
  const HapticSessionSettings& settings() const { return m_settings; }
  /// The scene the session shares.
  const CollisionScene& scene() const { return *m_scene; }

private:
  std::shared_ptr<const CollisionScene> m_scene;
  HapticSessionSettings m_settings;
  std::unique_ptr<ProxySolver> m_solver; // large (fixed buffers): on the heap
  std::unique_ptr<ServoForce> m_servo;
  std::shared_ptr<TickDynamics> m_dynamics;
  ProxyStartPlacement m_placement;
  bool m_placed = false;
  std::uint64_t m_tick = 0;
};

} // namespace proxima
