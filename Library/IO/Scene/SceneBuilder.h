// From a scene description to the CollisionScene the proxy runs on: meshes read and scaled,
// point normals made where shading asks for them and the file has none, objects placed by their
// poses, texture images read. Off the haptic thread, like everything that reads files.
#pragma once

#include "Geometry/SphereTree.h"
#include "IO/InputChecks/InputError.h"
#include "IO/Scene/SceneDescription.h"
#include "Proxy/CollisionScene.h"
#include "Tissue/TetMesh.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace proxima
{

/// Where an object's point normals came from.
enum class NormalsSource
{
  /// The mesh file has none and none were made: the object cannot be shaded.
  None,
  /// The mesh file's own.
  File,
  /// Made by withFeatureAngleNormals, because the object asks for shading and the file has none.
  Computed
};

/// "none", "file" or "computed", for reports.
const char* normalsSourceName(NormalsSource source);

/// What a report says about one object of a built scene, in the order of the description.
struct LoadedObject
{
  /// The mesh file as it was read.
  std::string mesh;
  /// Triangles of the built mesh.
  std::uint32_t numTriangles = 0;
  /// Of them, those of zero area to double precision (TriangleMesh::numDegenerateTriangles).
  std::uint32_t numDegenerateTriangles = 0;
  /// True if the proxy shades the object (shading On, or Auto with normals in the file).
  bool shaded = false;
  /// Where the object's point normals came from.
  NormalsSource normals = NormalsSource::None;
  /// The feature angle the normals were made with (when `normals` is Computed).
  double featureAngleDegrees = 0.0;
  /// True if the mesh has texture coordinates.
  bool texCoords = false;
  /// For a tissue object, its solid's tetrahedra (0 for a rigid one).
  std::uint32_t tetrahedra = 0;
};

/// A tissue object's solid as the scene was built: its tetrahedra at rest in the scene's frame,
/// whose boundary (boundarySoup) is the object's mesh, point for point.
struct LoadedTissue
{
  /// The scene object.
  std::uint32_t object = 0;
  /// The tetrahedra, placed.
  TetMesh tets;
  /// Wall time of reading or making them (s).
  double seconds = 0.0;
};

/// A built scene, ready for the proxy, with what a report says about it.
struct LoadedScene
{
  /// On the heap so that its address, which a ProxySolver keeps, stays put when this moves.
  std::unique_ptr<CollisionScene> scene;
  /// One entry per object, in the order of the description.
  std::vector<LoadedObject> objects;
  /// The tissue objects' solids, in the order of the objects (IO/Scene/SceneTissue.h couples
  /// them).
  std::vector<LoadedTissue> tissues;
  /// What the scene was built from (its bodies are made from it: IO/Scene/SceneBodies.h).
  SceneDescription description;
  /// Wall time of reading meshes and images and preparing the meshes.
  double readMilliseconds = 0.0;
  /// Wall time of building the sphere trees.
  double treeBuildMilliseconds = 0.0;
};

/// Builds the scene of `description`. For each object, in order: reads the mesh with its scale;
/// with shading On and no point normals in the file, makes them with the object's feature angle;
/// places points and normals by the pose; reads the texture images (an image used twice with
/// the same channel is read once and shared); builds the mesh and its sphere tree with `options`.
/// Shading Auto shades exactly when the mesh file has point normals. A tissue object's mesh is
/// wrapped and filled with tetrahedra (or they are read from its `tets` file), and its surface
/// is their boundary.
///
/// Throws InputError for a mesh or image that cannot be used (the reader's, naming that file),
/// and for texture maps on a mesh without texture coordinates (naming the scene file and the
/// object's location when the description came from a file, else the mesh), and as meshTissue
/// and readTetMeshFile do for a tissue. Throws
/// std::invalid_argument for a description without objects.
LoadedScene buildScene(const SceneDescription& description,
                       const SphereTreeOptions& options = SphereTreeOptions{});

/// readSceneFile, then buildScene.
LoadedScene loadSceneFile(const std::string& path,
                          const SphereTreeOptions& options = SphereTreeOptions{});

} // namespace proxima
