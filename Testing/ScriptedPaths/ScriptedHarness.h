// One scripted case (DESIGN.md section 7): a scene, a finger path and the invariants of section 4,
// run in lockstep mode (runLockstep + SimulatedDevice) with the oracle looking at every tick.
#pragma once

#include "ProxyOracle.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticState.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/ServoParameters.h"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace proxima::scripted
{

struct ScriptedCase
{
  std::string name;
  const CollisionScene* scene = nullptr;
  const oracle::MeshOracle* oracle = nullptr;
  ProxyParameters proxy;
  ServoParameters servo;
  FingerPath path;
  double rate = 1000.0;
  /// Where the proxy starts. Default: the path's first point, raised along +z in steps of one
  /// radius until it is 1.5 radii clear of the mesh (a default path may start within a radius of
  /// the top, e.g. "slide" skims at half a radius; the proxy cannot start inside).
  std::optional<Vec3> start;
  /// Ticks on which the device reports a NaN finger (the tick must be refused, force held).
  std::set<std::uint64_t> nanTicks;
  /// Ticks on which the device reports this position instead of the path's (a jump, a huge
  /// value, an infinity): refused exactly when it is not finite.
  std::map<std::uint64_t, Vec3> fingerOverrides;
  /// Keep the trace (golden files, comparisons).
  bool keepTrace = false;
};

struct ScriptedOutcome
{
  oracle::InvariantStats stats;
  std::vector<HapticState> trace;
  Vec3 start;
  double skin = 0.0;
  double seconds = 0.0;
};

/// Runs the case tick by tick through runLockstep and checks each tick (a)-(f).
ScriptedOutcome runScriptedCase(const ScriptedCase& scriptedCase);

/// Prints the summary line (std::cout), records the worst margins as test properties, and fails
/// the current test for every kind of violation.
void expectInvariants(const std::string& name, const ScriptedOutcome& outcome);

/// The golden trace format: tick,t,finger xyz,proxy xyz,force xyz,contacts,iterations (solve_ns
/// left out: it is the one field that is not deterministic).
std::string goldenCsv(const std::vector<HapticState>& trace);

/// Compares `trace` with Golden/<name>.csv in the source tree within 1e-12 relative, or rewrites
/// that file when the environment variable PROXIMA_UPDATE_GOLDEN is 1.
void expectMatchesGolden(const std::string& name, const std::vector<HapticState>& trace);

} // namespace proxima::scripted
