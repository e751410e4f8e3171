// One tick of the lockstep composition: read the device, run the proxy step on that sample, run
// the force stage on the fresh proxy (age 0), write the force. The lockstep runner, the threaded
// runtime's record of each proxy update and the VTK layer's lockstep pictures all run this.
#pragma once

#include "Runtime/ProxyStep.h"
#include "Runtime/ServoForce.h"

#include <cstdint>

namespace proxima
{

struct LockstepTick
{
  DeviceSample sample;
  ProxyStepOutcome outcome;
  ServoForceOutput force;
};

/// The force stage's input for a proxy step that just ran on `sample`.
ServoForceInput freshForceInput(const DeviceSample& sample, const ProxyStepOutcome& outcome,
                                double time, std::uint64_t sceneVersion);

/// Reads `device` at `time`, steps the solver and the force stage, and writes the force.
LockstepTick stepLockstepTick(double time, ProxySolver& solver, HapticDevice& device,
                              ServoForce& servo, std::uint64_t sceneVersion = 0);

} // namespace proxima
