// Run time against error (DESIGN.md section 5; Documentation/Performance.md): every knob that
// trades one for the other is set in turn, one setting at a time off the defaults, and for each
// setting the same sliding path is
//   - timed: the proxy update alone, every tick of several passes (median, p99, p99.9 of all
//     ticks and of the ticks that end in contact);
//   - checked: one more pass with the oracle of Testing/ScriptedPaths on every tick (worst
//     penetration, contact gap, local-minimum residual, free-path error; CGAL and 128-bit
//     arithmetic, independent of the kernel);
//   - and the paper's Figure 6 is run with the setting's parameters: the force direction's error
//     against the round cylinder's normal on a ten-sided prism (mean and max, degrees).
// Writes one JSON object per setting (a JSON array) to the file given as the first argument;
// Tools/performance-report.sh turns it into the table and the Pareto plot.
//
// With --scaling, the default setting instead on icospheres of 20k to 1.3M triangles and on the
// shared meshes (each scaled to a 25 cm diagonal): time, error, tree build time and memory
// against triangle count.
//
// Usage: BenchTimeVersusError OUT.json [subdivisions=8] [passes=5]
//        BenchTimeVersusError --scaling OUT.json [passes=5] [one shared mesh's file name]
#include "ProxyOracle.h"

#include "Geometry/ProceduralMeshes.h"
#include "IO/Mesh/MeshReader.h"
#include "Proxy/ProxySolver.h"
#include "Paths/PathGenerators.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace
{
using namespace proxima;

constexpr double kRadius = 0.001;
constexpr double kEdge = 0.0005;
constexpr double kRate = 1000.0;
constexpr double kPi = 3.14159265358979323846;

struct Setting
{
  std::string knob;
  std::string value;
  bool isDefault = false;
  ProxyParameters proxy;
  SphereTreeOptions tree;
  SurfaceMaterial material;
};

// One setting off the defaults per knob value; the default first.
std::vector<Setting> settings()
{
  std::vector<Setting> all;
  auto add = [&](const std::string& knob, const std::string& value,
                 const std::function<void(Setting&)>& change) {
    Setting s;
    s.proxy.radius = kRadius;
    s.knob = knob;
    s.value = value;
    change(s);
    all.push_back(s);
  };
  add("default", "", [](Setting& s) { s.isDefault = true; });
  for (double f : {0.0, 1.0, 4.0, 8.0})
  {
    add("leafSizeFactor", std::to_string(f).substr(0, 3),
        [f](Setting& s) { s.tree.leafSizeFactor = f; });
  }
  for (std::uint32_t n : {1u, 2u, 8u, 16u})
  {
    add("maxLeafSpheresPerNode", std::to_string(n),
        [n](Setting& s) { s.tree.maxLeafSpheresPerNode = n; });
  }
  for (double skin : {1e-13, 1e-11, 1e-10, 1e-9, 1e-8})
  {
    char text[32];
    std::snprintf(text, sizeof text, "%.0e m", skin);
    add("skin", text, [skin](Setting& s) { s.proxy.skin = skin; });
  }
  for (int cap : {1, 2, 4, 8, 32})
  {
    add("maxIterations", std::to_string(cap), [cap](Setting& s) { s.proxy.maxIterations = cap; });
  }
  add("temporalCoherence", "off", [](Setting& s) { s.proxy.temporalCoherence = false; });
  for (double m : {0.25, 4.0})
  {
    add("coherenceMargin", std::to_string(m).substr(0, 4) + " r",
        [m](Setting& s) { s.proxy.coherenceMargin = m * kRadius; });
  }
  add("shading", "on", [](Setting& s) { s.material.shading = true; });
  add("friction", "mu_s 0.5, mu_d 0.3, b 1", [](Setting& s) {
    s.material.staticFriction = 0.5;
    s.material.dynamicFriction = 0.3;
    s.material.viscosity = 1.0;
  });
  return all;
}

// The press-and-stroke of BenchProxyTick: into the surface point nearest the top of the box
// (on a real mesh the box's top centre may be over a hole), 2 cm across at 5 cm/s.
FingerPath slidingPath(const CollisionObject& object)
{
  const Aabb& bounds = object.mesh.bounds();
  SphereTreeScratch scratch;
  const NearestTriangle top =
    object.tree.nearest(object.mesh, Vec3{bounds.center().x, bounds.center().y, bounds.upper.z},
                        bounds.diagonal(), scratch);
  PressAndStroke p;
  p.strokeDirection = Vec3{1, 0, 0};
  p.strokeLength = 0.02;
  p.surfacePoint = top.closest.point - Vec3{0.5 * p.strokeLength, 0, 0};
  p.approachHeight = 3.0 * kRadius;
  p.depth = 2.0 * kRadius;
  p.speed = 0.05;
  return makePressAndStrokePath(p, kRate);
}

double quantile(std::vector<double> values, double q)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[rank == 0 ? 0 : rank - 1];
}

// Figure 6 (Tools/figure6.py): a ten-sided prism of radius 5 cm with radial point normals, the
// finger circling 2 mm inside the facets; the force's direction against the radial direction
// at the finger's angle over one turn, after a quarter turn to settle.
void figure6(const Setting& setting, double& meanError, double& maxError)
{
  const int sides = 10;
  const double prismRadius = 0.05;
  const int perTurn = 3600;
  TriangleMesh mesh;
  MeshError error;
  mesh.build(makePrism(sides, prismRadius, 0.1), error);
  CollisionScene scene;
  SurfaceMaterial material = setting.material;
  material.staticFriction = material.dynamicFriction = material.viscosity = 0.0;
  scene.addObject(std::move(mesh), setting.tree, material);
  ProxySolver solver;
  solver.setScene(&scene, setting.proxy);
  const double fingerRadius = prismRadius * std::cos(kPi / sides) - 0.002;
  const double start = prismRadius + 0.005;
  solver.resetProxy({start, 0, 0});
  for (int i = 0; i <= 100; ++i)
  {
    solver.update({start + (fingerRadius - start) * i / 100.0, 0, 0});
  }
  double sum = 0.0;
  int count = 0;
  maxError = 0.0;
  for (int i = 1; i <= perTurn + perTurn / 4; ++i)
  {
    const double angle = 2.0 * kPi * i / perTurn;
    const Vec3 finger{fingerRadius * std::cos(angle), fingerRadius * std::sin(angle), 0.0};
    const ProxyTickResult r = solver.update(finger);
    if (i <= perTurn / 4)
    {
      continue;
    }
    const Vec3 force = r.proxy - finger;
    const double n = std::hypot(force.x, force.y);
    if (n == 0.0)
    {
      continue;
    }
    const double cosine = (force.x * std::cos(angle) + force.y * std::sin(angle)) / n;
    const double degrees = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / kPi;
    sum += degrees;
    ++count;
    maxError = std::max(maxError, degrees);
  }
  meanError = count > 0 ? sum / count : 0.0;
}

std::string number(double value)
{
  char text[40];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}
} // namespace

namespace
{
// Times `soup` under `setting`, then checks one more pass with the oracle; one JSON object.
std::string measure(const TriangleSoup& soup, const oracle::MeshOracle& oracle,
                    const Setting& setting, int passes, const std::string& meshName)
{
  TriangleMesh mesh;
  MeshError error;
  mesh.build(soup, error);
  CollisionScene scene;
  const auto buildStart = std::chrono::steady_clock::now();
  scene.addObject(std::move(mesh), setting.tree, setting.material);
  const double buildSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
  const FingerPath path = slidingPath(scene.objects.front());

  // Timing: the update alone.
  ProxySolver solver;
  solver.setScene(&scene, setting.proxy);
  std::vector<double> all;
  std::vector<double> contact;
  double iterations = 0.0;
  for (int pass = 0; pass < passes; ++pass)
  {
    solver.resetProxy(path.positions.front());
    for (const Vec3& finger : path.positions)
    {
      const auto begin = std::chrono::steady_clock::now();
      const ProxyTickResult r = solver.update(finger);
      const double ns =
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - begin).count();
      all.push_back(ns);
      if (r.numContacts > 0)
      {
        contact.push_back(ns);
      }
      iterations += r.iterations;
    }
  }

  // Accuracy: one more pass, the oracle on every tick.
  solver.resetProxy(path.positions.front());
  oracle::TickChecker checker(oracle, scene, setting.proxy,
                              oracle::OracleSettings::forScene(scene.diagonal(), solver.skin()));
  checker.reset(path.positions.front());
  std::uint64_t tick = 0;
  for (const Vec3& finger : path.positions)
  {
    checker.check(tick++, finger, solver.update(finger));
  }
  const oracle::InvariantStats& s = checker.stats();
  for (const std::string& message : s.messages)
  {
    std::fprintf(stderr, "%s, %s %s: %s\n", meshName.c_str(), setting.knob.c_str(),
                 setting.value.c_str(), message.c_str());
  }
  double meanFigure6 = 0.0;
  double maxFigure6 = 0.0;
  figure6(setting, meanFigure6, maxFigure6);

  const double penetration = std::max(0.0, -s.minClearance);
  const double gap = std::max(0.0, s.maxGap);
  std::string json =
    "  {\"mesh\": \"" + meshName + "\", \"knob\": \"" + setting.knob + "\", \"value\": \"" +
    setting.value + "\", \"default\": " + (setting.isDefault ? "true" : "false") +
    ", \"triangles\": " + std::to_string(oracle.numTriangles()) +
    ", \"ticks\": " + std::to_string(path.size()) + ", \"passes\": " + std::to_string(passes) +
    ", \"tick_median_ns\": " + number(quantile(all, 0.5)) +
    ", \"tick_p99_ns\": " + number(quantile(all, 0.99)) +
    ", \"tick_p999_ns\": " + number(quantile(all, 0.999)) +
    ", \"contact_median_ns\": " + number(quantile(contact, 0.5)) +
    ", \"contact_p99_ns\": " + number(quantile(contact, 0.99)) +
    ", \"contact_p999_ns\": " + number(quantile(contact, 0.999)) +
    ", \"iterations_per_tick\": " + number(iterations / static_cast<double>(all.size())) +
    ", \"tree_build_s\": " + number(buildSeconds) + ", \"tree_bytes_per_triangle\": " +
    number(static_cast<double>(scene.objects.front().tree.memoryBytes()) /
           static_cast<double>(oracle.numTriangles())) +
    ", \"skin_m\": " + number(solver.skin()) + ", \"penetration_m\": " + number(penetration) +
    ", \"gap_m\": " + number(gap) + ", \"residual_m\": " + number(s.maxResidual) +
    ", \"free_path_error_m\": " + number(s.maxFreePathError) +
    ", \"oracle_failures\": " + std::to_string(s.failures()) +
    ", \"cap_ticks\": " + std::to_string(s.capTicks) +
    ", \"figure6_mean_deg\": " + number(meanFigure6) +
    ", \"figure6_max_deg\": " + number(maxFigure6) + "}";
  std::fprintf(stderr,
               "%-22s %-24s contact median %8.0f ns, p99.9 %8.0f ns; residual %.2g m, "
               "gap %.2g m, penetration %.2g m; figure 6 max %.2f deg\n",
               setting.knob.c_str(), setting.value.c_str(), quantile(contact, 0.5),
               quantile(contact, 0.999), s.maxResidual, gap, penetration, maxFigure6);
  return json;
}

// A shared mesh scaled so that its box diagonal is 25 cm (the scale of a hand-held object; the
// files carry no units), or nothing when the file is absent.
bool sharedMesh(const std::string& name, TriangleSoup& soup)
{
  const std::string file = std::string(PROXIMA_SHARED_MESHES) + "/" + name;
  if (!std::filesystem::exists(file))
  {
    return false;
  }
  soup = readMeshFile(file);
  Aabb box;
  for (const Vec3& p : soup.points)
  {
    box.expand(p);
  }
  soup = readMeshFile(file, 0.25 / box.diagonal());
  return true;
}

oracle::MeshOracle oracleFor(const TriangleSoup& soup)
{
  std::vector<TriangleCorners> corners;
  for (const auto& t : soup.triangles)
  {
    corners.push_back({soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]});
  }
  return oracle::MeshOracle(std::move(corners));
}

bool write(const char* file, const std::string& json)
{
  std::FILE* out = std::fopen(file, "w");
  if (out == nullptr || std::fputs(json.c_str(), out) < 0)
  {
    std::perror(file);
    return false;
  }
  std::fclose(out);
  return true;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf(stderr,
                 "usage: %s OUT.json [subdivisions=8] [passes=5]\n"
                 "       %s --scaling OUT.json [passes=5] [one shared mesh]\n",
                 argv[0], argv[0]);
    return 2;
  }
  if (std::string(argv[1]) == "--scaling")
  {
    // The default setting on icospheres of 20k to 1.3M triangles and on every shared mesh.
    const int passes = argc > 3 ? std::atoi(argv[3]) : 5;
    const Setting defaults = settings().front();
    std::string json = "[\n";
    bool first = true;
    auto run = [&](const TriangleSoup& soup, const std::string& name) {
      const oracle::MeshOracle oracle = oracleFor(soup);
      json += std::string(first ? "" : ",\n") + measure(soup, oracle, defaults, passes, name);
      first = false;
    };
    const std::string only = argc > 4 ? argv[4] : "";
    for (std::uint32_t subdivisions = 5; only.empty() && subdivisions <= 8; ++subdivisions)
    {
      const double radius = kEdge * std::ldexp(1.0, static_cast<int>(subdivisions)) / 1.05;
      run(makeIcosphere(subdivisions, radius), "icosphere " + std::to_string(subdivisions));
    }
    for (const char* name :
         {"stanford-bunny.obj", "Angel_decimated.vtp", "M3x10_screw.stl", "fandisk.off",
          "teapot.obj", "spot_triangulated.obj", "VH_M_Liver.glb", "cranium_bone_iso075mm.ply"})
    {
      TriangleSoup soup;
      if (!only.empty() && only != name)
      {
        continue;
      }
      if (sharedMesh(name, soup))
      {
        soup.pointNormals.clear();
        run(soup, name);
      }
      else
      {
        std::fprintf(stderr, "%s: not in %s, skipped\n", name, PROXIMA_SHARED_MESHES);
      }
    }
    json += "\n]\n";
    return write(argv[2], json) ? 0 : 1;
  }

  const auto subdivisions = static_cast<std::uint32_t>(argc > 2 ? std::atoi(argv[2]) : 8);
  const int passes = argc > 3 ? std::atoi(argv[3]) : 5;
  // Edges of 0.5 mm (BenchProxyTick): an icosphere's edge is about 1.05 R / 2^s.
  const double sphereRadius = kEdge * std::ldexp(1.0, static_cast<int>(subdivisions)) / 1.05;
  const TriangleSoup soup = makeIcosphere(subdivisions, sphereRadius);
  const oracle::MeshOracle oracle = oracleFor(soup);
  std::fprintf(stderr, "%zu triangles; oracle ready\n", oracle.numTriangles());
  std::string json = "[\n";
  bool first = true;
  for (const Setting& setting : settings())
  {
    json += std::string(first ? "" : ",\n") +
            measure(soup, oracle, setting, passes, "icosphere " + std::to_string(subdivisions));
    first = false;
  }
  json += "\n]\n";
  return write(argv[1], json) ? 0 : 1;
}
