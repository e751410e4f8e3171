// loadSceneFile on scenes written here: the built meshes are the files' meshes scaled and placed
// exactly as the pose says (points against the analytic transform, normals turned, texture
// coordinates untouched), normals are made only where shading asks for them, texture images are
// read and shared, and a mesh or image that cannot be used is its reader's InputError.
#include "Geometry/ProceduralMeshes.h"
#include "IO/Mesh/MeshWriter.h"
#include "IO/Scene/SceneBuilder.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using proxima::LoadedScene;
using proxima::NormalsSource;
using proxima::TriangleSoup;
using proxima::Vec3;

class SceneBuilder : public testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::temp_directory_path() /
            ("proxima-scene-build-" + std::to_string(::getpid()) + "-" + info->name());
    fs::create_directories(m_dir / "meshes");
    proxima::writeMeshFile(pathOf("meshes/box.obj"), box());
    proxima::writeMeshFile(pathOf("meshes/sphere.obj"), sphere());
  }
  void TearDown() override { fs::remove_all(m_dir); }

  std::string pathOf(const std::string& name) const { return (m_dir / name).string(); }

  std::string write(const std::string& name, const std::string& content) const
  {
    std::ofstream(pathOf(name), std::ios::binary) << content;
    return pathOf(name);
  }

  /// A box without normals, with texture coordinates that differ per point.
  static TriangleSoup box()
  {
    TriangleSoup soup = proxima::makeBox({0.01, 0.02, 0.03});
    for (std::size_t i = 0; i < soup.points.size(); ++i)
    {
      const double k = static_cast<double>(i);
      soup.texCoords.push_back({0.125 * k, 1.0 - 0.0625 * k});
    }
    return soup;
  }

  /// A sphere of radius 0.05 about the origin with radial unit normals, no texture coordinates.
  static TriangleSoup sphere() { return proxima::makeIcosphere(2, 0.05); }

  /// A 4 x 4 grey PNG.
  std::string writeImage(const std::string& name) const
  {
    std::vector<float> pixels(16);
    for (std::size_t i = 0; i < pixels.size(); ++i)
    {
      pixels[i] = static_cast<float>(i) / 15.0f;
    }
    const std::string path = pathOf(name);
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(output);
    OIIO::ImageSpec spec(4, 4, 1, OIIO::TypeDesc::UINT8);
    EXPECT_TRUE(output->open(path, spec));
    EXPECT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    output->close();
    return path;
  }

  static std::string refusal(const std::string& scene, std::string* path = nullptr)
  {
    try
    {
      (void)proxima::loadSceneFile(scene);
    }
    catch (const proxima::InputError& error)
    {
      if (path != nullptr)
      {
        *path = error.path();
      }
      return error.what();
    }
    return "";
  }

  fs::path m_dir;
};

Vec3 faceNormal(const TriangleSoup& soup, std::size_t t)
{
  const auto& index = soup.triangles[t];
  const Vec3& a = soup.points[index[0]];
  return proxima::normalizedOrZero(
    proxima::cross(soup.points[index[1]] - a, soup.points[index[2]] - a));
}

TEST_F(SceneBuilder, PosesMovePointsAndTurnNormals)
{
  // The box: scale 2, then 120 degrees about (1, 1, 1), which takes x to y, y to z and z to x:
  // R (x, y, z) = (z, x, y); then moved by (0.1, 0.2, 0.3). Shading on makes its normals.
  // The sphere: 180 degrees about x as a quaternion, R (x, y, z) = (x, -y, -z) with exact
  // matrix entries, then up by 0.5; it keeps the file's normals and shades (auto).
  const std::string scene = write("scene.json", R"({
    "version": 1,
    "objects": [
      {"mesh": "meshes/box.obj", "scale": 2,
       "pose": {"translation": [0.1, 0.2, 0.3], "rotation": {"axis_angle_deg": [1, 1, 1, 120]}},
       "material": {"shading": "on"}},
      {"mesh": "meshes/sphere.obj",
       "pose": {"translation": [0, 0, 0.5], "rotation": {"quaternion": [0, 1, 0, 0]}},
       "material": {"shading": "auto"}}
    ]})");
  const LoadedScene loaded = proxima::loadSceneFile(scene);
  ASSERT_EQ(loaded.scene->objects.size(), 2u);
  ASSERT_EQ(loaded.objects.size(), 2u);

  const TriangleSoup boxSoup = box();
  const proxima::TriangleMesh& boxMesh = loaded.scene->objects[0].mesh;
  ASSERT_EQ(boxMesh.numTriangles(), boxSoup.triangles.size());
  ASSERT_TRUE(boxMesh.hasPointNormals());
  ASSERT_TRUE(boxMesh.hasTexCoords());
  // Split at the box's edges: 3 normals at each of the 8 corners.
  EXPECT_EQ(boxMesh.numPoints(), 24u);
  const auto boxPlaced = [](const Vec3& p) {
    return Vec3{2.0 * p.z + 0.1, 2.0 * p.x + 0.2, 2.0 * p.y + 0.3};
  };
  const auto boxTurned = [](const Vec3& n) { return Vec3{n.z, n.x, n.y}; };
  for (std::uint32_t t = 0; t < boxMesh.numTriangles(); ++t)
  {
    const proxima::TriangleCorners& c = boxMesh.corners(t);
    const Vec3 built[3] = {c.a, c.b, c.c};
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t fileIndex = boxSoup.triangles[t][k];
      const std::uint32_t builtIndex = boxMesh.indices(t)[k];
      const Vec3 expected = boxPlaced(boxSoup.points[fileIndex]);
      EXPECT_LE(proxima::maxAbsComponent(built[k] - expected), 1e-15)
        << "triangle " << t << " corner " << k;
      // The normal made in the file's frame is the face's, turned with the box.
      EXPECT_LE(proxima::maxAbsComponent(boxMesh.pointNormals()[builtIndex] -
                                         boxTurned(faceNormal(boxSoup, t))),
                1e-15)
        << "triangle " << t << " corner " << k;
      EXPECT_EQ(boxMesh.texCoords()[builtIndex].u, boxSoup.texCoords[fileIndex].u);
      EXPECT_EQ(boxMesh.texCoords()[builtIndex].v, boxSoup.texCoords[fileIndex].v);
    }
  }

  const TriangleSoup sphereSoup = sphere();
  const proxima::TriangleMesh& sphereMesh = loaded.scene->objects[1].mesh;
  ASSERT_EQ(sphereMesh.numPoints(), sphereSoup.points.size());
  ASSERT_TRUE(sphereMesh.hasPointNormals());
  for (std::size_t i = 0; i < sphereSoup.points.size(); ++i)
  {
    const Vec3& p = sphereSoup.points[i];
    const Vec3& n = sphereSoup.pointNormals[i];
    EXPECT_EQ(sphereMesh.points()[i], (Vec3{p.x, -p.y, -p.z + 0.5})) << "point " << i;
    EXPECT_EQ(sphereMesh.pointNormals()[i], (Vec3{n.x, -n.y, -n.z})) << "point " << i;
    // Still radial about the moved centre.
    EXPECT_LE(proxima::maxAbsComponent(sphereMesh.pointNormals()[i] -
                                       (sphereMesh.points()[i] - Vec3{0, 0, 0.5}) / 0.05),
              1e-12);
  }

  EXPECT_EQ(loaded.objects[0].mesh, pathOf("meshes/box.obj"));
  EXPECT_EQ(loaded.objects[0].numTriangles, 12u);
  EXPECT_TRUE(loaded.objects[0].shaded);
  EXPECT_EQ(loaded.objects[0].normals, NormalsSource::Computed);
  EXPECT_EQ(loaded.objects[0].featureAngleDegrees, 30.0);
  EXPECT_TRUE(loaded.objects[0].texCoords);
  EXPECT_TRUE(loaded.scene->objects[0].material.shading);
  EXPECT_EQ(loaded.objects[1].numTriangles, 320u);
  EXPECT_TRUE(loaded.objects[1].shaded);
  EXPECT_EQ(loaded.objects[1].normals, NormalsSource::File);
  EXPECT_FALSE(loaded.objects[1].texCoords);
  // The scene's bounds take both placed objects: the box reaches x = 0.1 + 2 * 0.03.
  EXPECT_NEAR(loaded.scene->objects[0].mesh.bounds().upper.x, 0.16, 1e-15);
  EXPECT_NEAR(loaded.scene->objects[1].mesh.bounds().upper.z, 0.55, 1e-15);
}

TEST_F(SceneBuilder, WithoutAPoseTheFileIsKeptBitForBit)
{
  const LoadedScene loaded =
    proxima::loadSceneFile(write("plain.json", R"({"objects": [{"mesh": "meshes/sphere.obj"}]})"));
  const TriangleSoup soup = sphere();
  const proxima::TriangleMesh& mesh = loaded.scene->objects[0].mesh;
  ASSERT_EQ(mesh.numPoints(), soup.points.size());
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    EXPECT_EQ(mesh.points()[i], soup.points[i]);
    EXPECT_EQ(mesh.pointNormals()[i], soup.pointNormals[i]);
  }
  // Shading off by default, though the file has normals.
  EXPECT_FALSE(loaded.objects[0].shaded);
  EXPECT_FALSE(loaded.scene->objects[0].material.shading);
  EXPECT_EQ(loaded.objects[0].normals, NormalsSource::File);
}

TEST_F(SceneBuilder, ShadingAutoOnAMeshWithoutNormalsMakesNone)
{
  const LoadedScene loaded = proxima::loadSceneFile(write(
    "auto.json", R"({"objects": [{"mesh": "meshes/box.obj", "material": {"shading": "auto"}}]})"));
  EXPECT_FALSE(loaded.objects[0].shaded);
  EXPECT_EQ(loaded.objects[0].normals, NormalsSource::None);
  EXPECT_FALSE(loaded.scene->objects[0].mesh.hasPointNormals());
}

TEST_F(SceneBuilder, MaterialsAndSharedTextureImages)
{
  writeImage("bumps.png");
  const LoadedScene loaded = proxima::loadSceneFile(write("textured.json", R"({"objects": [
    {"mesh": "meshes/box.obj",
     "material": {"static_friction": 0.5, "dynamic_friction": 0.3, "viscosity": 2,
                  "textures": [{"image": "bumps.png", "role": "bump", "amplitude": 0.0001},
                               {"image": "bumps.png", "role": "friction"}]}},
    {"mesh": "meshes/box.obj", "pose": {"translation": [1, 0, 0]},
     "material": {"textures": [{"image": "bumps.png", "role": "bump", "amplitude": -0.0002}]}}
  ]})"));
  const proxima::SurfaceMaterial& first = loaded.scene->objects[0].material;
  EXPECT_EQ(first.staticFriction, 0.5);
  EXPECT_EQ(first.dynamicFriction, 0.3);
  EXPECT_EQ(first.viscosity, 2.0);
  ASSERT_EQ(first.textures.size(), 2u);
  EXPECT_EQ(first.textures[0].role, proxima::TextureRole::Bump);
  EXPECT_EQ(first.textures[0].amplitude, 0.0001);
  EXPECT_EQ(first.textures[1].role, proxima::TextureRole::Friction);
  ASSERT_TRUE(first.textures[0].image);
  EXPECT_EQ(first.textures[0].image->width(), 4);
  // One image file with one channel is read once, whichever object uses it.
  const proxima::SurfaceMaterial& second = loaded.scene->objects[1].material;
  ASSERT_EQ(second.textures.size(), 1u);
  EXPECT_EQ(second.textures[0].image.get(), first.textures[0].image.get());
  EXPECT_EQ(first.textures[1].image.get(), first.textures[0].image.get());
  EXPECT_EQ(second.textures[0].amplitude, -0.0002);
  EXPECT_FALSE(second.hasFriction());
}

TEST_F(SceneBuilder, TexturesOnAMeshWithoutTextureCoordinates)
{
  writeImage("bumps.png");
  const std::string scene = write("untextured.json", R"({"objects": [
    {"mesh": "meshes/box.obj"},
    {"mesh": "meshes/sphere.obj",
     "material": {"textures": [{"image": "bumps.png", "role": "bump", "amplitude": 0.0001}]}}]})");
  std::string path;
  EXPECT_EQ(refusal(scene, &path), scene + ": objects[1].material.textures: the mesh " +
                                     pathOf("meshes/sphere.obj") +
                                     " has no texture coordinates, which texture maps need");
  EXPECT_EQ(path, scene);
}

TEST_F(SceneBuilder, TexturesOnAMeshWithoutTextureCoordinatesInADescriptionMadeInCode)
{
  proxima::SceneDescription description;
  proxima::SceneObject object;
  object.mesh = pathOf("meshes/sphere.obj");
  object.material.textures.push_back({writeImage("bumps.png"), proxima::TextureRole::Bump, 1e-4,
                                      proxima::TextureChannel::Luminance});
  description.objects.push_back(object);
  try
  {
    (void)proxima::buildScene(description);
    ADD_FAILURE() << "accepted";
  }
  catch (const proxima::InputError& error)
  {
    EXPECT_EQ(error.path(), object.mesh);
    EXPECT_EQ(error.defect(), "has no texture coordinates, which texture maps need");
  }
}

TEST_F(SceneBuilder, AMissingMeshIsTheMeshReadersError)
{
  std::string path;
  const std::string message =
    refusal(write("missing.json",
                  R"({"objects": [{"mesh": "meshes/box.obj"}, {"mesh": "meshes/gone.stl"}]})"),
            &path);
  EXPECT_EQ(path, pathOf("meshes/gone.stl"));
  EXPECT_TRUE(message.starts_with(pathOf("meshes/gone.stl") + ": cannot open the file")) << message;
}

TEST_F(SceneBuilder, ABadMeshIsTheMeshReadersError)
{
  write("meshes/nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  std::string path;
  const std::string message =
    refusal(write("nan.json", R"({"objects": [{"mesh": "meshes/nan.obj"}]})"), &path);
  EXPECT_EQ(path, pathOf("meshes/nan.obj"));
  EXPECT_NE(message.find("non-finite coordinate"), std::string::npos) << message;
}

TEST_F(SceneBuilder, AMissingImageIsTheImageReadersError)
{
  std::string path;
  const std::string message =
    refusal(write("noimage.json", R"({"objects": [{"mesh": "meshes/box.obj",
    "material": {"textures": [{"image": "absent.png", "role": "bump", "amplitude": 0.001}]}}]})"),
            &path);
  EXPECT_EQ(path, pathOf("absent.png"));
  EXPECT_TRUE(message.starts_with(pathOf("absent.png") + ": cannot open")) << message;
}

TEST_F(SceneBuilder, ADescriptionWithoutObjectsIsAProgrammingError)
{
  EXPECT_THROW((void)proxima::buildScene(proxima::SceneDescription{}), std::invalid_argument);
}

} // namespace
