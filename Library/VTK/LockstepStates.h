// HapticStates from a lockstep run: the haptic tick every runner runs (Runtime/HapticStep.h) on a
// virtual clock, each tick's state with its contacts kept for drawing. Deterministic, so image
// tests and documentation figures do not depend on timing.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Proxy/ProxyParameters.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticDevice.h"
#include "Runtime/HapticState.h"
#include "Runtime/ServoParameters.h"
#include "Runtime/TickDynamics.h"

#include <functional>

namespace proxima::vtk
{

/// Plays `path` at `rate` through `scene` from the path's first sample and hands every tick's
/// state to `onState`, in order; `onState` returns false to stop early.
void playLockstepStates(const CollisionScene& scene, const ProxyParameters& parameters,
                        const ServoParameters& servo, const FingerPath& path, double rate,
                        const std::function<bool(const HapticState&)>& onState);

/// The same with the finger read from `device` (a recording device around the path's, say) over
/// the ticks of `path`; with `bodies` (the scene's), each tick ends with their dynamics step.
void playLockstepStates(const CollisionScene& scene, const ProxyParameters& parameters,
                        const ServoParameters& servo, const FingerPath& path, double rate,
                        HapticDevice& device,
                        const std::function<bool(const HapticState&)>& onState,
                        TickDynamics* bodies = nullptr);

} // namespace proxima::vtk
