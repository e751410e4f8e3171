// proxima._proxima.make_path and read_path: the finger paths of `proxima path`, as arrays.
#include "Bindings.h"

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "IO/Mesh/MeshReader.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/Scene/SceneBuilder.h"
#include "Paths/PathGenerators.h"

#include <stdexcept>

namespace proxima::python
{
namespace
{
// The kinds of `proxima path`: the default kinds, and probe.
bool knownKind(const std::string& kind)
{
  for (const std::string& name : defaultPathKinds())
  {
    if (kind == name)
    {
      return true;
    }
  }
  return kind == "probe";
}

FingerPath makePath(const std::string& kind, const std::string& mesh, const std::string& scene,
                    double scale, double radius, double rate, std::uint64_t seed, double duration,
                    double stretch)
{
  if (!knownKind(kind))
  {
    throw InputError("kind", "'" + kind + "' is not a path kind of proxima path");
  }
  if (mesh.empty() == scene.empty())
  {
    throw InputError("--mesh", "give a mesh or a scene file, one of the two");
  }
  // The ranges `proxima path` checks its options against.
  const auto check = [](const char* option, double value, const ParameterRange& range) {
    if (!range.contains(value))
    {
      throw InputError(option, "must be " + describeRange(range) + ", not " + shortNumber(value));
    }
  };
  check("--scale", scale, kMeshScaleRange);
  check("--radius", radius, kProxyRadiusRange);
  check("--rate", rate, kScriptedRateRange);
  check("--duration", duration, kPathDurationRange);
  if (stretch != 0.0)
  {
    check("--stretch", stretch, ParameterRange{0.0, true, 0.1, " m"});
  }
  if (kind == "probe")
  {
    checkTickCount(duration * rate, rate, kDefaultMaxTicks,
                   "--duration " + shortNumber(duration) + " s");
  }
  // The surfaces the path is placed on: the mesh with a tree of its own, or the scene's objects
  // as placed.
  std::vector<ProbeSurface> surfaces;
  TriangleMesh triangles;
  SphereTree tree;
  LoadedScene loaded;
  if (scene.empty())
  {
    triangles = loadTriangleMesh(mesh, scale);
    tree.build(triangles);
    surfaces.push_back({&triangles, &tree});
  }
  else
  {
    loaded = loadSceneFile(scene);
    for (const CollisionObject& object : loaded.scene->objects)
    {
      surfaces.push_back({&object.mesh, &object.tree});
    }
  }
  if (kind == "probe")
  {
    ProbeOptions probe;
    probe.seed = seed;
    probe.duration = duration;
    probe.rate = rate;
    return makeProbePath(surfaces, probe);
  }
  SurfacePathOptions surface;
  surface.radius = radius;
  surface.rate = rate;
  surface.seed = seed;
  surface.stretch = stretch;
  try
  {
    return makeSurfacePath(kind, surfaces, surface);
  }
  catch (const std::runtime_error& error)
  {
    throw InputError(scene.empty() ? mesh : scene, kind + ": " + error.what());
  }
}
} // namespace

void addPathBindings(py::module_& module)
{
  module.def(
    "make_path",
    [](const std::string& kind, const std::string& mesh, const std::string& scene, double scale,
       double radius, double rate, std::uint64_t seed, double duration, double stretch) {
      FingerPath path;
      {
        py::gil_scoped_release released;
        path = makePath(kind, mesh, scene, scale, radius, rate, seed, duration, stretch);
      }
      return fingerPathArray(path);
    },
    py::arg("kind"), py::kw_only(), py::arg("mesh") = "", py::arg("scene") = "",
    py::arg("scale") = 1.0, py::arg("radius") = 0.001, py::arg("rate") = 1000.0,
    py::arg("seed") = 1, py::arg("duration") = ProbeOptions{}.duration, py::arg("stretch") = 0.0,
    "The finger path `proxima path KIND` writes, as an (N, 4) array t, x, y, z.");
  module.def(
    "read_path", [](const std::string& file) { return fingerPathArray(readFingerPathFile(file)); },
    py::arg("file"), "A finger path CSV (t,x,y,z) as an (N, 4) array.");
  module.def(
    "path_kinds",
    [] {
      std::vector<std::string> kinds = defaultPathKinds();
      kinds.push_back("probe");
      return kinds;
    },
    "The kinds make_path takes.");
}

} // namespace proxima::python
