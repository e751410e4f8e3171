// A scene file packed for the server: each file it names goes once, under a local name with the
// reader's extension, holding the file's bytes; the scene's paths become those names; a file
// that cannot be read is refused by name before anything is sent.
#include "IO/InputChecks/InputError.h"
#include "Net/Private/SceneBundlePacking.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <unistd.h>

namespace proxima::detail
{
namespace
{

namespace fs = std::filesystem;

const char* const kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const char* const kQuad = "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 2 3\nf 1 3 4\n";

class SceneBundlePacking : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    m_folder = fs::temp_directory_path() /
               ("proxima-bundle-" + std::string(test->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(m_folder);
    fs::create_directories(m_folder / "meshes");
  }
  void TearDown() override { fs::remove_all(m_folder); }

  std::string write(const std::string& name, const std::string& text) const
  {
    const fs::path path = m_folder / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  fs::path m_folder;
};

TEST_F(SceneBundlePacking, EachFileGoesOnceUnderALocalNameWithItsBytes)
{
  write("meshes/triangle.obj", kTriangle);
  write("quad.obj", kQuad);
  const std::string scene =
    write("scene.json", R"({"version": 1, "objects": [{"mesh": "meshes/triangle.obj"},
                      {"mesh": "quad.obj", "pose": {"translation": [0, 0, 1]}},
                      {"mesh": "meshes/triangle.obj", "pose": {"translation": [2, 0, 0]}}]})");
  const net::SceneBundle bundle = packSceneFile(scene);
  EXPECT_EQ(bundle.scene_name(), scene);
  ASSERT_EQ(bundle.files_size(), 2) << "the triangle is named twice but sent once";
  std::map<std::string, const net::BundledFile*> byLocal;
  for (const net::BundledFile& file : bundle.files())
  {
    byLocal[file.local_name()] = &file;
    EXPECT_EQ(fs::path(file.local_name()).extension(), ".obj");
    EXPECT_EQ(file.local_name().find('/'), std::string::npos) << "a name the server can write";
  }
  ASSERT_EQ(byLocal.size(), 2u);
  const auto json = nlohmann::json::parse(bundle.scene_json());
  const auto& objects = json.at("objects");
  ASSERT_EQ(objects.size(), 3u);
  // Each object's mesh is now a bundled file's name, holding the bytes of the file it named.
  const std::string expected[] = {kTriangle, kQuad, kTriangle};
  for (std::size_t i = 0; i < 3; ++i)
  {
    const std::string local = objects[i].at("mesh").get<std::string>();
    ASSERT_TRUE(byLocal.count(local)) << local;
    EXPECT_EQ(byLocal[local]->data(), expected[i]) << "object " << i;
    EXPECT_TRUE(fs::exists(byLocal[local]->client_name())) << byLocal[local]->client_name();
  }
  EXPECT_EQ(objects[0].at("mesh"), objects[2].at("mesh"));
  EXPECT_NE(objects[0].at("mesh"), objects[1].at("mesh"));
  // What is not a path stays as the file gave it.
  EXPECT_EQ(objects[1].at("pose").at("translation"), nlohmann::json::parse("[0, 0, 1]"));
}

TEST_F(SceneBundlePacking, AMissingMeshIsRefusedByName)
{
  const std::string scene =
    write("scene.json", R"({"version": 1, "objects": [{"mesh": "meshes/gone.obj"}]})");
  try
  {
    packSceneFile(scene);
    FAIL() << "a scene naming a missing mesh was packed";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("gone.obj"), std::string::npos) << error.what();
  }
}

TEST_F(SceneBundlePacking, ABrokenSceneFileIsRefusedAsALocalRunRefusesIt)
{
  write("meshes/triangle.obj", kTriangle);
  const std::string scene =
    write("scene.json", R"({"version": 1, "objects": [{"mesh": "meshes/triangle.obj",
                            "scale": -2}]})");
  try
  {
    packSceneFile(scene);
    FAIL() << "a negative scale was packed";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("scale"), std::string::npos) << error.what();
  }
}

} // namespace
} // namespace proxima::detail
