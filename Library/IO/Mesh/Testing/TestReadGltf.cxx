// glTF specifics: every mesh instance of the default scene, placed by its node's global
// transform (parents included), merged into one soup. The shared liver has no node transforms,
// so this file builds a small scene that has them.
#include "IO/Mesh/MeshReader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;

// One triangle (0,0,0) (1,0,0) (0,1,0): 36 bytes of float positions, 3 uint16 indices, padding.
const char* kBuffer = "data:application/octet-stream;base64,"
                      "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=";

std::string sceneJson()
{
  return std::string(R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0, 2]}],
  "nodes": [
    {"translation": [0, 0, 5], "children": [1]},
    {"mesh": 0, "translation": [10, 0, 0]},
    {"mesh": 0, "scale": [2, 2, 2]}
  ],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": 44, "uri": ")") +
         kBuffer + R"("}],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": 36},
    {"buffer": 0, "byteOffset": 36, "byteLength": 6}
  ],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}
  ]
})";
}

TEST(ReadGltf, NodeTransformsAreAppliedAndInstancesMerged)
{
  const fs::path dir = fs::temp_directory_path() / ("proxima-gltf-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "scene.gltf").string();
  std::ofstream(path) << sceneJson();

  const proxima::TriangleSoup soup = proxima::readMeshFile(path, 0.5);
  fs::remove_all(dir);
  ASSERT_EQ(soup.triangles.size(), 2u);
  proxima::MeshError error;
  proxima::TriangleMesh mesh;
  ASSERT_TRUE(mesh.build(soup, error)) << error.message;
  // Instance 1: parent (0,0,5) then own (10,0,0): x in [10, 11], z = 5. Instance 2: scaled by 2
  // at the origin: x, y in [0, 2], z = 0. Then everything times 0.5.
  const double tolerance = 1e-6;
  EXPECT_NEAR(mesh.bounds().lower.x, 0.0, tolerance);
  EXPECT_NEAR(mesh.bounds().upper.x, 5.5, tolerance);
  EXPECT_NEAR(mesh.bounds().upper.y, 1.0, tolerance);
  EXPECT_NEAR(mesh.bounds().lower.z, 0.0, tolerance);
  EXPECT_NEAR(mesh.bounds().upper.z, 2.5, tolerance);
}
} // namespace
