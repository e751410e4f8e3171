#include "StressSupport.h"

#include "Geometry/TriangleMesh.h"
#include "IO/Mesh/MeshWriter.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "Proxy/CollisionScene.h"
#include "Paths/PathGenerators.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace proxima::stress
{

std::uint64_t Random::next()
{
  std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double Random::uniform()
{
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

double Random::logUniform(double lo, double hi)
{
  return std::pow(10.0, uniform(std::log10(lo), std::log10(hi)));
}

int Random::integer(int lo, int hi)
{
  const auto span = static_cast<std::uint64_t>(hi - lo + 1);
  return lo + static_cast<int>(next() % span);
}

Vec3 Random::direction()
{
  // Rejection from the cube: uniform on the sphere, and never a zero vector.
  for (;;)
  {
    const Vec3 v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    const double n = norm(v);
    if (n > 1e-3 && n <= 1.0)
    {
      return v / n;
    }
  }
}

Rotation Rotation::random(Random& random)
{
  // A uniform unit quaternion turned into its matrix.
  Vec3 a = random.direction();
  const double w = random.uniform(-1, 1);
  const double s = std::sqrt(1.0 - w * w);
  a = a * s;
  const double x = a.x;
  const double y = a.y;
  const double z = a.z;
  Rotation r;
  r.x = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
  r.y = {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
  r.z = {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)};
  return r;
}

TriangleSoup transform(TriangleSoup soup, const Rotation& rotation, const Vec3& offset)
{
  for (Vec3& p : soup.points)
  {
    p = rotation(p) + offset;
  }
  for (Vec3& n : soup.pointNormals)
  {
    n = rotation(n);
  }
  return soup;
}

FingerPath transform(FingerPath path, const Rotation& rotation, const Vec3& offset)
{
  for (Vec3& p : path.positions)
  {
    p = rotation(p) + offset;
  }
  return path;
}

FingerPath randomWander(Random& random, const Aabb& box, int legs, double speed, double rate)
{
  auto somewhere = [&]() {
    return Vec3{random.uniform(box.lower.x, box.upper.x), random.uniform(box.lower.y, box.upper.y),
                random.uniform(box.lower.z, box.upper.z)};
  };
  std::vector<FingerPath> parts;
  Vec3 from = somewhere();
  for (int leg = 0; leg < legs; ++leg)
  {
    const Vec3 to = somewhere();
    const double duration = std::max(distance(from, to) / speed, 2.0 / rate);
    parts.push_back(makeSlidePath(from, to, duration, rate));
    from = to;
  }
  return concatenatePaths(parts, rate);
}

namespace
{
double environmentNumber(const char* name, double fallback)
{
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0')
  {
    return fallback;
  }
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  return end != text && std::isfinite(value) ? value : fallback;
}

// The tick of the oracle's first message ("tick N (reproduce: ...)"), or -1.
long long firstFailingTick(const oracle::InvariantStats& stats)
{
  for (const std::string& message : stats.messages)
  {
    const auto at = message.find("tick ");
    if (at != std::string::npos)
    {
      return std::atoll(message.c_str() + at + 5);
    }
  }
  return -1;
}

scripted::ScriptedCase scriptedCase(const StressCase& c, const CollisionScene& scene,
                                    const oracle::MeshOracle& oracle)
{
  scripted::ScriptedCase s;
  s.name = c.name;
  s.scene = &scene;
  s.oracle = &oracle;
  s.proxy = c.proxy;
  s.servo.stiffness = c.proxy.stiffness;
  s.path = c.path;
  s.rate = c.rate;
  s.start = c.start;
  s.fingerOverrides = c.fingerOverrides;
  return s;
}

// The rows of `path` up to and including the time of `tick`, led by `start` one tick earlier.
FingerPath prefixThroughTick(const FingerPath& path, const Vec3& start, long long tick, double rate)
{
  FingerPath prefix;
  const double t0 = path.startTime();
  const double end = t0 + static_cast<double>(tick) / rate;
  prefix.append(t0 - 1.0 / rate, start);
  std::size_t hint = 0;
  for (std::size_t i = 0; i < path.size() && path.times[i] < end; ++i)
  {
    prefix.append(path.times[i], path.positions[i]);
  }
  prefix.append(end, path.positionAt(end, hint));
  return prefix;
}
} // namespace

CaseSeeds caseSeeds(std::uint64_t defaultBase, int defaultCount)
{
  CaseSeeds seeds;
  seeds.base = defaultBase;
  const char* text = std::getenv("PROXIMA_STRESS_SEED");
  if (text != nullptr && std::string(text) == "random")
  {
    seeds.base =
      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  }
  else if (text != nullptr && *text != '\0')
  {
    seeds.base = std::strtoull(text, nullptr, 10);
  }
  const double scale = environmentNumber("PROXIMA_STRESS_SCALE", 1.0);
  const double cases = environmentNumber("PROXIMA_STRESS_CASES", defaultCount * scale);
  seeds.count = std::max(1, static_cast<int>(std::lround(cases)));
  std::cout << "[stress] seeds " << seeds.base << " to " << seeds.base + seeds.count - 1
            << " (replay one: PROXIMA_STRESS_SEED=<seed> PROXIMA_STRESS_CASES=1)\n";
  return seeds;
}

void runCases(std::uint64_t defaultBase, int defaultCount,
              const std::function<void(Random&, StressCase&)>& make)
{
  const CaseSeeds seeds = caseSeeds(defaultBase, defaultCount);
  for (int k = 0; k < seeds.count; ++k)
  {
    StressCase c;
    c.seed = seeds.base + static_cast<std::uint64_t>(k);
    Random random(c.seed);
    make(random, c);
    runStressCase(c);
  }
}

oracle::InvariantStats runStressCase(const StressCase& c)
{
  TriangleMesh mesh;
  MeshError error;
  TriangleSoup soup = c.soup;
  if (!mesh.build(std::move(soup), error))
  {
    ADD_FAILURE() << c.name << " (seed " << c.seed << "): invalid stress mesh: " << error.message;
    return {};
  }
  CollisionScene scene;
  scene.addObject(std::move(mesh));
  const oracle::MeshOracle oracle(scene);
  const scripted::ScriptedOutcome outcome =
    scripted::runScriptedCase(scriptedCase(c, scene, oracle));
  const std::string name = c.name + " (seed " + std::to_string(c.seed) + ")";
  scripted::expectInvariants(name, outcome);
  for (const std::string& message : outcome.stats.messages)
  {
    std::cout << "[stress] " << name << ": " << message << "\n";
  }
  if (outcome.stats.failures() == 0)
  {
    return outcome.stats;
  }

  // A reproducer: the mesh and the shortest prefix of the path that reaches the first failure.
  const std::filesystem::path folder = std::filesystem::current_path() / "stress-failures";
  std::filesystem::create_directories(folder);
  std::string stem = c.name;
  for (char& ch : stem)
  {
    if (ch == '/' || ch == ' ')
    {
      ch = '-';
    }
  }
  stem += "-" + std::to_string(c.seed);
  const std::string meshFile = (folder / (stem + ".obj")).string();
  const std::string pathFile = (folder / (stem + ".csv")).string();
  const long long tick = firstFailingTick(outcome.stats);
  try
  {
    writeMeshFile(meshFile, c.soup);
    const FingerPath prefix = prefixThroughTick(
      c.path, outcome.start, tick < 0 ? static_cast<long long>(outcome.stats.ticks) : tick, c.rate);
    writeFingerPathFile(pathFile, prefix);
  }
  catch (const std::exception& e)
  {
    std::cout << "[stress] could not write the reproducer: " << e.what() << "\n";
  }
  std::cout << "[stress] FAILED " << name << " at tick " << tick << "; reproduce with\n"
            << "[stress]   PROXIMA_STRESS_SEED=" << c.seed
            << " PROXIMA_STRESS_CASES=1 and the same --gtest_filter, or\n"
            << "[stress]   proxima run --mesh " << meshFile << " --path " << pathFile
            << " --radius " << oracle::str(c.proxy.radius) << " --out trace.csv"
            << (c.fingerOverrides.empty() ? "" : "  (the file lacks the case's injected fingers)")
            << "\n";
  return outcome.stats;
}

} // namespace proxima::stress
