// What the haptic threads show the rest of the program: one consistent snapshot of the proxy, the
// finger, the force and the contacts, handed over without locks (ThreadedRuntime::latestState).
// Plain values only, so a copy is a snapshot.
#pragma once

#include "Core/Vec3.h"

#include <cstdint>

namespace proxima
{

/// One active contact, as drawn by the representations: a plane through `point` with `normal`,
/// and the friction cone around the normal.
struct ContactSnapshot
{
  /// Nearest point of the touched primitive to the proxy centre.
  Vec3 point;
  /// The constraint plane's normal, into free space.
  Vec3 normal;
  std::uint32_t object = 0;
  std::uint32_t triangle = 0;
  /// Static and dynamic friction coefficients here (0 without friction): the cone half-angles are
  /// atan(staticFriction) and atan(dynamicFriction).
  double staticFriction = 0.0;
  double dynamicFriction = 0.0;
};

struct HapticState
{
  /// Servo tick that produced this state, and its time on the runtime's clock (seconds).
  std::uint64_t tick = 0;
  double time = 0.0;
  Vec3 finger;
  Vec3 proxy;
  double proxyRadius = 0.0;
  /// Force commanded to the device (on the finger), after clamping, rate limiting and fading.
  Vec3 force;
  int numContacts = 0;
  ContactSnapshot contacts[3];
  /// Static friction held the proxy (the finger is inside a cone: sticking); otherwise a contact
  /// with friction is slipping.
  bool stuck = false;
  bool frictionLimited = false;
  /// The force is being faded out: the proxy loop stalled or the device was lost.
  bool fading = false;
  bool deviceLost = false;
  /// Version of the scene the proxy loop used for this state (ThreadedRuntime::publishScene).
  std::uint64_t sceneVersion = 0;
};

} // namespace proxima
