#include "Geometry/ProceduralMeshes.h"
#include "IO/Mesh/MeshReader.h"
#include "IO/Mesh/MeshWriter.h"
#include "IO/Testing/FileSizeLimit.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;

class WriteMeshFile : public testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::temp_directory_path() /
            ("proxima-io-write-" + std::to_string(::getpid()) + "-" + info->name());
    fs::create_directories(m_dir);
  }
  void TearDown() override { fs::remove_all(m_dir); }
  std::string path(const std::string& name) const { return (m_dir / name).string(); }
  fs::path m_dir;
};

TEST_F(WriteMeshFile, ObjRoundTripIsExact)
{
  const proxima::TriangleSoup sphere = proxima::makeIcosphere(2, 0.05);
  proxima::writeMeshFile(path("sphere.obj"), sphere);
  const proxima::TriangleSoup back = proxima::readMeshFile(path("sphere.obj"));
  ASSERT_EQ(back.points.size(), sphere.points.size());
  ASSERT_EQ(back.triangles, sphere.triangles);
  // 17 significant digits: every double comes back bit for bit.
  EXPECT_EQ(back.points, sphere.points);
  EXPECT_EQ(back.pointNormals, sphere.pointNormals);
}

TEST_F(WriteMeshFile, StlPlyAndVtpRoundTrip)
{
  const proxima::TriangleSoup box = proxima::makeBox({0.1, 0.2, 0.3});
  for (const char* name : {"box.stl", "box.ply", "box.vtp", "BOX.STL"})
  {
    proxima::writeMeshFile(path(name), box);
    const proxima::TriangleSoup back = proxima::readMeshFile(path(name));
    EXPECT_EQ(back.triangles.size(), box.triangles.size()) << name;
    EXPECT_EQ(back.points.size(), box.points.size()) << name;
  }
}

// VTK's OBJ and PLY writers return success on a full disk. The target is a link to /dev/null,
// written in place and never limited, so only the check of VTK's own file can catch the cut.
TEST_F(WriteMeshFile, AWriterCutShortByAFullDiskIsAnError)
{
  const proxima::TriangleSoup sphere = proxima::makeIcosphere(3, 0.05);
  for (const char* name : {"sphere.obj", "sphere.stl", "sphere.ply"})
  {
    fs::create_symlink("/dev/null", path(name));
    const std::string message = proxima::testing_support::messageUnderFileSizeLimit(
      4096, [&] { proxima::writeMeshFile(path(name), sphere); });
    EXPECT_EQ(message, path(name) + ": cannot write the file (File too large)");
  }
}

TEST_F(WriteMeshFile, RefusesUnwritablePathAndUnknownFormat)
{
  const proxima::TriangleSoup box = proxima::makeBox({1, 1, 1});
  EXPECT_THROW(proxima::writeMeshFile(path("no/such/folder/box.obj"), box), proxima::InputError);
  EXPECT_THROW(proxima::writeMeshFile(path("box.off"), box), proxima::InputError);
  EXPECT_THROW(proxima::writeMeshFile(path("box.xyz"), box), proxima::InputError);
  try
  {
    proxima::writeMeshFile(path("no/such/folder/box.obj"), box);
  }
  catch (const proxima::InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("box.obj: cannot write the file"), std::string::npos)
      << error.what();
  }
}
} // namespace
