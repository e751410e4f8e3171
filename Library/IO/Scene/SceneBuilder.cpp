#include "IO/Scene/SceneBuilder.h"

#include "IO/Mesh/MeshReader.h"
#include "IO/MeshPreparation/PointNormals.h"
#include "IO/Scene/SceneFile.h"
#include "IO/Scene/TextureImageFile.h"
#include "IO/TissueMeshing/TetMeshFile.h"
#include "IO/TissueMeshing/TissueMeshing.h"
#include "Tissue/TetBoundary.h"

#include <chrono>
#include <map>
#include <stdexcept>
#include <utility>

namespace proxima
{
namespace
{
double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

// Images by (file, channel): objects that share a texture share one copy of it.
using ImageCache =
  std::map<std::pair<std::string, TextureChannel>, std::shared_ptr<const TextureImage>>;

std::shared_ptr<const TextureImage> imageFor(const SceneTexture& texture, ImageCache& cache)
{
  const auto key = std::make_pair(texture.image, texture.channel);
  auto it = cache.find(key);
  if (it == cache.end())
  {
    it = cache
           .emplace(key, std::make_shared<const TextureImage>(
                           readTextureImage(texture.image, texture.channel)))
           .first;
  }
  return it->second;
}
// A tissue's tetrahedra in the scene's frame: read from its .vtu file and scaled as the mesh
// is, or made by wrapping and filling the (scaled) mesh; then placed by the object's pose.
TetMesh tissueTets(const SceneObject& object, const TriangleSoup& scaled)
{
  TetMesh tets;
  if (!object.tissue.tets.empty())
  {
    tets = readTetMeshFile(object.tissue.tets);
    for (Vec3& point : tets.points)
    {
      point = point * object.scale;
    }
  }
  else
  {
    TissueMeshingOptions options;
    options.tetSize = object.tissue.tetSize;
    tets = meshTissue(scaled, options, object.mesh).tets;
  }
  TriangleSoup points;
  points.points = std::move(tets.points);
  tets.points = posed(std::move(points), object.pose).points;
  return tets;
}
} // namespace

const char* normalsSourceName(NormalsSource source)
{
  switch (source)
  {
    case NormalsSource::None: return "none";
    case NormalsSource::File: return "file";
    case NormalsSource::Computed: return "computed";
  }
  return "none";
}

LoadedScene buildScene(const SceneDescription& description, const SphereTreeOptions& options)
{
  if (description.objects.empty())
  {
    throw std::invalid_argument("buildScene: a scene description without objects");
  }
  LoadedScene loaded;
  loaded.scene = std::make_unique<CollisionScene>();
  loaded.description = description;
  ImageCache images;
  for (std::size_t i = 0; i < description.objects.size(); ++i)
  {
    const SceneObject& object = description.objects[i];
    const auto readStart = std::chrono::steady_clock::now();
    TriangleSoup soup = readMeshFile(object.mesh, object.scale);

    if (!object.material.textures.empty() && soup.texCoords.empty())
    {
      // The kernel would skip the maps without a word: refuse the combination instead.
      if (description.path.empty())
      {
        throw InputError(object.mesh, "has no texture coordinates, which texture maps need");
      }
      throw InputError(description.path, "objects[" + std::to_string(i) +
                                           "].material.textures: the mesh " + object.mesh +
                                           " has no texture coordinates, which texture maps need");
    }

    LoadedObject info;
    info.mesh = object.mesh;
    info.normals = soup.pointNormals.empty() ? NormalsSource::None : NormalsSource::File;
    const SceneShading shading = object.material.shading;
    if (shading == SceneShading::On && info.normals == NormalsSource::None)
    {
      // In the file's frame, before the pose: the normals belong to the shape.
      soup = withFeatureAngleNormals(soup, object.material.featureAngleDegrees);
      info.normals = NormalsSource::Computed;
      info.featureAngleDegrees = object.material.featureAngleDegrees;
    }
    if (object.hasTissue)
    {
      // The object's surface is its solid's boundary over the solid's own points, so that each
      // step's positions are the surface's points as they are (Tissue/TissueDynamics.h).
      const auto tissueStart = std::chrono::steady_clock::now();
      LoadedTissue tissue;
      tissue.object = static_cast<std::uint32_t>(i);
      tissue.tets = tissueTets(object, soup);
      tissue.seconds = millisecondsSince(tissueStart) / 1000.0;
      soup = boundarySoup(tissue.tets);
      info.tetrahedra = static_cast<std::uint32_t>(tissue.tets.tets.size());
      loaded.tissues.push_back(std::move(tissue));
    }
    else
    {
      soup = posed(std::move(soup), object.pose);
    }
    info.texCoords = !soup.texCoords.empty();

    SurfaceMaterial material;
    material.shading = shading == SceneShading::On ||
                       (shading == SceneShading::Auto && info.normals == NormalsSource::File);
    material.staticFriction = object.material.staticFriction;
    material.dynamicFriction = object.material.dynamicFriction;
    material.viscosity = object.material.viscosity;
    material.stiffness = object.material.stiffness;
    material.stiffnessRegions = object.material.stiffnessRegions;
    for (const SceneTexture& texture : object.material.textures)
    {
      material.textures.push_back(
        TextureMap{imageFor(texture, images), texture.role, texture.amplitude});
    }
    info.shaded = material.shading;

    TriangleMesh mesh = buildTriangleMesh(std::move(soup), object.mesh);
    info.numTriangles = mesh.numTriangles();
    info.numDegenerateTriangles = mesh.numDegenerateTriangles();
    loaded.readMilliseconds += millisecondsSince(readStart);

    const auto buildStart = std::chrono::steady_clock::now();
    loaded.scene->addObject(std::move(mesh), options, material);
    loaded.treeBuildMilliseconds += millisecondsSince(buildStart);
    loaded.objects.push_back(std::move(info));
  }
  return loaded;
}

LoadedScene loadSceneFile(const std::string& path, const SphereTreeOptions& options)
{
  return buildScene(readSceneFile(path), options);
}

} // namespace proxima
