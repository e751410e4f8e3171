// OFF coordinates arrive in double precision, as the file's text writes them: every coordinate the
// reader returns equals strtod of the file's own number, the oracle here, which is independent of
// the reader's parsing. OpenMesh's parser alone gives floats, about 7 digits, which moved the
// surface of fandisk.off by up to a nanometre.
#include "IO/Mesh/MeshReader.h"

#include "IO/Testing/ScratchFolderTest.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{

/// Every vertex's three coordinates parsed by strtod from the text of an OFF file whose vertex
/// lines hold three numbers each (no normals, colours or texture coordinates), in file order.
std::vector<proxima::Vec3> positionsByStrtod(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  std::string header;
  std::getline(file, header);
  std::size_t numVertices = 0;
  std::size_t numFaces = 0;
  std::size_t numEdges = 0;
  file >> numVertices >> numFaces >> numEdges;
  std::vector<proxima::Vec3> positions;
  std::string word[3];
  for (std::size_t v = 0; v < numVertices && file >> word[0] >> word[1] >> word[2]; ++v)
  {
    positions.push_back({std::strtod(word[0].c_str(), nullptr),
                         std::strtod(word[1].c_str(), nullptr),
                         std::strtod(word[2].c_str(), nullptr)});
  }
  EXPECT_EQ(positions.size(), numVertices) << path;
  return positions;
}

/// How many coordinates float cannot hold: the test proves nothing about precision without them.
std::size_t countBeyondFloat(const std::vector<proxima::Vec3>& positions)
{
  std::size_t count = 0;
  for (const proxima::Vec3& p : positions)
  {
    for (double coordinate : {p.x, p.y, p.z})
    {
      count += static_cast<double>(static_cast<float>(coordinate)) != coordinate ? 1 : 0;
    }
  }
  return count;
}

void expectSamePositions(const std::vector<proxima::Vec3>& read,
                         const std::vector<proxima::Vec3>& expected, const std::string& what)
{
  ASSERT_EQ(read.size(), expected.size()) << what;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < read.size(); ++i)
  {
    if (!(read[i] == expected[i]) && ++mismatches <= 5)
    {
      ADD_FAILURE() << what << ": point " << i << " is (" << read[i].x << ", " << read[i].y << ", "
                    << read[i].z << "), the file says (" << expected[i].x << ", " << expected[i].y
                    << ", " << expected[i].z << ")";
    }
  }
  EXPECT_EQ(mismatches, 0u) << what;
}

class ReadOffPrecision : public proxima::testing_support::ScratchFolderTest
{
protected:
  ReadOffPrecision()
    : ScratchFolderTest("proxima-io-off-")
  {}
};

TEST_F(ReadOffPrecision, CoordinatesEqualTheTextParsedInDouble)
{
  // Up to 17 significant digits, with signs and exponents, one below float's normal range (float
  // keeps it only as a subnormal); every coordinate but -1.5 is beyond float. The quad makes the
  // reader triangulate, so the points also pass through VTK's triangle filter.
  std::ostringstream text;
  text.precision(17);
  text << "OFF\n5 2 0\n"
       << "0.1234567890123 0.001000000001 -0.98765432109876\n"
       << "1.0000000000000002 2.5e-3 0.30000000000000004\n"
       << 1e-3 + 1e-12 << " 1.17549435e-39 3.14159265358979312\n"
       << "12345.678901234567 -0.000123456789012345 7e-1\n"
       << "-1.5 0.7071067811865476 1e-12\n"
       << "3 0 1 2\n4 1 2 3 4\n";
  const std::string path = write("double.off", text.str());
  const std::vector<proxima::Vec3> expected = positionsByStrtod(path);
  ASSERT_EQ(expected.size(), 5u);
  ASSERT_EQ(countBeyondFloat(expected), 14u);

  const proxima::TriangleSoup soup = proxima::readMeshFile(path);
  EXPECT_EQ(soup.triangles.size(), 3u);
  expectSamePositions(soup.points, expected, "soup");
  // And on into the kernel's mesh, which keeps the soup's points as they are.
  expectSamePositions(proxima::loadTriangleMesh(path).points(), expected, "TriangleMesh");
}

TEST_F(ReadOffPrecision, NormalsAfterTheCoordinatesLeaveThemInDouble)
{
  // NOFF: three more numbers on each vertex line; the double coordinates must still be the
  // vertex's first three numbers, not shifted into its normal.
  const std::string path = write("normals.off", "NOFF\n3 1 0\n"
                                                "0.1234567890123 0 0 0 0 1\n"
                                                "1 0.001000000001 0 0 0 1\n"
                                                "0 1 -0.98765432109876 0 0 1\n"
                                                "3 0 1 2\n");
  const proxima::TriangleSoup soup = proxima::readMeshFile(path);
  ASSERT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.points[0].x, std::strtod("0.1234567890123", nullptr));
  EXPECT_EQ(soup.points[1].y, std::strtod("0.001000000001", nullptr));
  EXPECT_EQ(soup.points[2].z, std::strtod("-0.98765432109876", nullptr));
  ASSERT_EQ(soup.pointNormals.size(), 3u);
  EXPECT_EQ(soup.pointNormals[1], (proxima::Vec3{0, 0, 1}));
}

TEST_F(ReadOffPrecision, SharedFandiskEqualsItsText)
{
  const std::string path = std::string(PROXIMA_SHARED_MESHES) + "/fandisk.off";
  if (!std::filesystem::exists(path))
  {
    GTEST_SKIP() << "shared mesh not found: " << path
                 << " (set the CMake cache variable PROXIMA_SHARED_DATA)";
  }
  const std::vector<proxima::Vec3> expected = positionsByStrtod(path);
  // PROVENANCE.md: 12,946 triangles; the header counts 6,475 vertices.
  ASSERT_EQ(expected.size(), 6475u);
  // Most of its four-digit coordinates are no float: the check below would bite.
  EXPECT_GT(countBeyondFloat(expected), expected.size());
  expectSamePositions(proxima::readMeshFile(path).points, expected, "fandisk.off");
}

} // namespace
