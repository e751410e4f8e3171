// What every stress test shares (DESIGN.md section 4, numerical stability): recorded seeds, a
// portable random source, random rotations, and one call that runs a randomized case under the
// oracle of Testing/ScriptedPaths and, when the oracle objects, prints the seed and writes a
// reproducer (the mesh as OBJ and the shortest prefix of the path that still fails).
//
// Seeds: case k of a test runs with seed base + k, where base is PROXIMA_STRESS_SEED when set
// ("random" picks one from the clock and prints it) and the test's fixed default otherwise, so CI
// is deterministic and a local run can hunt. PROXIMA_STRESS_CASES overrides the number of cases
// (PROXIMA_STRESS_SEED=s PROXIMA_STRESS_CASES=1 replays one failed case), PROXIMA_STRESS_SCALE
// multiplies it (the sanitizer build runs a quarter).
#pragma once

#include "ScriptedHarness.h"

#include "Core/Aabb.h"
#include "Core/Vec3.h"
#include "Geometry/TriangleSoup.h"
#include "Runtime/FingerPath.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <string>

namespace proxima::stress
{

/// A small, portable generator (SplitMix64): the same seed gives the same case with any standard
/// library, which std::uniform_real_distribution does not promise.
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : m_state(seed)
  {}
  std::uint64_t next();
  /// Uniform in [0, 1).
  double uniform();
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// 10^u with u uniform in [log10(lo), log10(hi)): a scale spread evenly over decades.
  double logUniform(double lo, double hi);
  /// Uniform in [lo, hi].
  int integer(int lo, int hi);
  /// A uniform direction.
  Vec3 direction();

private:
  std::uint64_t m_state;
};

/// A proper rotation, stored as its three columns.
struct Rotation
{
  Vec3 x{1, 0, 0};
  Vec3 y{0, 1, 0};
  Vec3 z{0, 0, 1};
  Vec3 operator()(const Vec3& v) const { return x * v.x + y * v.y + z * v.z; }
  static Rotation random(Random& random);
};

/// Every point (and point normal) of `soup` rotated about the origin, then moved by `offset`.
TriangleSoup transform(TriangleSoup soup, const Rotation& rotation, const Vec3& offset = Vec3{});
/// Every row of `path` rotated about the origin, then moved by `offset`.
FingerPath transform(FingerPath path, const Rotation& rotation, const Vec3& offset = Vec3{});

/// A finger that visits `legs` random points of `box` in straight lines at `speed` (m/s).
FingerPath randomWander(Random& random, const Aabb& box, int legs, double speed, double rate);

/// The first seed of a test's cases and how many cases to run (see the file comment).
struct CaseSeeds
{
  std::uint64_t base = 0;
  int count = 0;
};
CaseSeeds caseSeeds(std::uint64_t defaultBase, int defaultCount);

/// One randomized case: a soup, its path and the proxy, with the seed that made them.
struct StressCase
{
  std::string name;
  std::uint64_t seed = 0;
  TriangleSoup soup;
  FingerPath path;
  ProxyParameters proxy;
  /// Default: the path's first point, raised until clear (ScriptedCase::start).
  std::optional<Vec3> start;
  std::map<std::uint64_t, Vec3> fingerOverrides;
  double rate = 1000.0;
};

/// The cases of one test: for each seed of caseSeeds(defaultBase, defaultCount), `make` builds
/// the case from a generator seeded with it (the case's seed is set already), and the case runs
/// through runStressCase.
void runCases(std::uint64_t defaultBase, int defaultCount,
              const std::function<void(Random&, StressCase&)>& make);

/// Runs the case tick by tick under the oracle and fails the current test for every violation;
/// on a failure also prints the seed and writes `<build>/stress-failures/<name>-<seed>.obj` and
/// `.csv` (the path up to the first failing tick, led by the proxy's start, so that
/// `proxima run --mesh X.obj --path X.csv --radius R` replays it). Returns the oracle's stats.
oracle::InvariantStats runStressCase(const StressCase& stressCase);

} // namespace proxima::stress
