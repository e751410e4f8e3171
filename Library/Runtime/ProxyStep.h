// The proxy-update step: the solver's tick on one device sample, timed. The lockstep runner and
// the threaded runtime's proxy thread both run exactly this.
#pragma once

#include "Proxy/ProxySolver.h"
#include "Runtime/HapticDevice.h"
#include "Runtime/HapticState.h"

#include <cstdint>

namespace proxima
{

struct ProxyStepOutcome
{
  ProxyTickResult result;
  /// The proxy after the step (held where it was when the finger was refused).
  Vec3 proxy;
  /// The sample held no usable finger (invalid, device lost, or not finite): the proxy held.
  bool refused = false;
  /// Wall time of the solver's update in nanoseconds: the one field that is not deterministic.
  std::int64_t solveNanoseconds = 0;
};

ProxyStepOutcome runProxyStep(ProxySolver& solver, const DeviceSample& sample);

/// The tick's active contacts as the render thread draws them, into `contacts`; returns how many.
int snapshotContacts(const ProxyTickResult& result, ContactSnapshot (&contacts)[3]);

} // namespace proxima
