#include "IO/Output/OutputError.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Testing/ScratchFolderTest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace
{
namespace fs = std::filesystem;
using proxima::namesSameFile;

class OutputIdentity : public proxima::testing_support::ScratchFolderTest
{
protected:
  OutputIdentity()
    : ScratchFolderTest("proxima-output-identity-")
  {}
};

TEST_F(OutputIdentity, OneFileHowEverItIsSpelled)
{
  const std::string mesh = write("mesh.obj", "v 0 0 0\n");
  EXPECT_TRUE(namesSameFile(mesh, mesh));
  EXPECT_TRUE(namesSameFile(mesh, (m_dir / "." / "mesh.obj").string()));
  fs::create_symlink(mesh, pathOf("link.obj"));
  EXPECT_TRUE(namesSameFile(pathOf("link.obj"), mesh));
  fs::create_hard_link(mesh, pathOf("hard.obj"));
  EXPECT_TRUE(namesSameFile(pathOf("hard.obj"), mesh));
}

TEST_F(OutputIdentity, TwoNewFilesAreOneWhenTheirPathsAre)
{
  EXPECT_TRUE(namesSameFile(pathOf("trace.csv"), (m_dir / "." / "trace.csv").string()));
  EXPECT_FALSE(namesSameFile(pathOf("trace.csv"), pathOf("summary.json")));
}

TEST_F(OutputIdentity, DifferentFilesAndDevicesAreNotOne)
{
  const std::string a = write("a.obj", "a");
  const std::string b = write("b.obj", "b");
  EXPECT_FALSE(namesSameFile(a, b));
  EXPECT_FALSE(namesSameFile(a, pathOf("new.obj")));
  EXPECT_FALSE(namesSameFile("/dev/null", "/dev/null"));
  EXPECT_FALSE(namesSameFile(a, ""));
}

TEST_F(OutputIdentity, RefusesAnInputAsOutputAndTwoOutputsInOneFile)
{
  const std::string mesh = write("mesh.obj", "v 0 0 0\n");
  try
  {
    proxima::refuseOverlappingFiles({{(m_dir / "." / "mesh.obj").string(), "--out"}},
                                    {{mesh, "--mesh"}});
    ADD_FAILURE() << "not refused";
  }
  catch (const proxima::OutputError& error)
  {
    EXPECT_EQ(std::string(error.what()), (m_dir / "." / "mesh.obj").string() +
                                           ": --out is the same file as --mesh, which it would "
                                           "overwrite");
  }
  try
  {
    proxima::refuseOverlappingFiles({{pathOf("t.csv"), "--out"}, {pathOf("t.csv"), "--summary"}},
                                    {{mesh, "--mesh"}});
    ADD_FAILURE() << "not refused";
  }
  catch (const proxima::OutputError& error)
  {
    EXPECT_EQ(std::string(error.what()),
              pathOf("t.csv") + ": --summary and --out name the same file; give each its own");
  }
  EXPECT_NO_THROW(proxima::refuseOverlappingFiles(
    {{pathOf("t.csv"), "--out"}, {"", "--summary"}, {"/dev/null", "--record-device"}},
    {{mesh, "--mesh"}, {"", "--scene"}}));
}
} // namespace
