// HapticStates from a lockstep run: the same proxy step and force stage as the runtime's threads
// (Runtime/ProxyStep.h, Runtime/ServoForce.h) on a virtual clock, with each tick's contacts kept
// for drawing. Deterministic, so image tests and documentation figures do not depend on timing.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Proxy/ProxyParameters.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticState.h"
#include "Runtime/ServoTick.h"

#include <functional>

namespace proxima::vtk
{

/// The state a tick leaves, as the threaded runtime publishes it: proxy, finger, force and the
/// active contacts with their friction coefficients.
HapticState hapticStateOf(std::uint64_t tick, double time, const Vec3& finger,
                          const ProxyTickResult& result, const Vec3& proxy, double proxyRadius,
                          const Vec3& force, bool fading);

/// Plays `path` at `rate` through `scene` from the path's first sample and hands every tick's
/// state to `onState`, in order; `onState` returns false to stop early.
void playLockstepStates(const CollisionScene& scene, const ProxyParameters& parameters,
                        const ServoParameters& servo, const FingerPath& path, double rate,
                        const std::function<bool(const HapticState&)>& onState);

} // namespace proxima::vtk
