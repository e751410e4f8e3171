// Bad files are refused with an InputError whose message is one line naming the file and the
// defect (DESIGN.md section 6), and VTK prints nothing of its own meanwhile.
#include "IO/MeshReader.h"

#include "ScratchFolderTest.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
namespace fs = std::filesystem;

class ReadBadInput : public proxima::testing_support::ScratchFolderTest
{
protected:
  ReadBadInput() : ScratchFolderTest("proxima-io-") {}


  /// Reads `path`, expects an InputError naming the file and containing `defect`, and expects
  /// that nothing reached stderr.
  static void expectRefused(const std::string& path, const std::string& defect)
  {
    testing::internal::CaptureStderr();
    std::string message;
    try
    {
      (void)proxima::readMeshFile(path);
    }
    catch (const proxima::InputError& error)
    {
      message = error.what();
      EXPECT_EQ(error.path(), path);
    }
    const std::string printed = testing::internal::GetCapturedStderr();
    ASSERT_FALSE(message.empty()) << path << " was accepted";
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(fs::path(path).filename().string()), std::string::npos) << message;
    EXPECT_NE(message.find(defect), std::string::npos) << "wanted '" << defect << "' in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(printed, "") << "printed while reading " << path;
  }

  /// Bytes that are no mesh format, the same on every run.
  static std::string garbage(std::size_t size)
  {
    std::string bytes(size, '\0');
    std::uint32_t state = 12345u;
    for (char& c : bytes)
    {
      state = state * 1664525u + 1013904223u;
      c = static_cast<char>(state >> 24);
    }
    return bytes;
  }

};

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST_F(ReadBadInput, ObjWithNanCoordinate)
{
  expectRefused(write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"),
                "line 3: vertex 3 has a non-finite coordinate (nan, 1, 0)");
}

TEST_F(ReadBadInput, ObjWithInfiniteCoordinate)
{
  expectRefused(write("inf.obj", "v 0 0 0\nv 1 0 -inf\nv 0 1 0\nf 1 2 3\n"),
                "vertex 2 has a non-finite coordinate (1, 0, -inf)");
  expectRefused(write("overflow.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"),
                "vertex 2 has a non-finite coordinate (inf, 0, 0)");
}

TEST_F(ReadBadInput, ObjWithUnreadableNumber)
{
  expectRefused(write("word.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n"),
                "line 2: cannot read 'zero' as a number in vertex 2");
}

TEST_F(ReadBadInput, ObjWithIndexOutOfRange)
{
  expectRefused(write("index.obj", std::string(kTriangleObj) + "f 1 2 3\nf 1 2 7\n"),
                "line 5: vertex index 7 is out of range (the file has 3 vertices)");
  expectRefused(write("zero.obj", std::string(kTriangleObj) + "f 0 1 2\n"), "vertex index 0 is out of range");
  expectRefused(write("relative.obj", std::string(kTriangleObj) + "f -1 -2 -4\n"),
                "vertex index -4 is out of range");
  expectRefused(write("texcoord.obj", std::string(kTriangleObj) + "vt 0 0\nf 1/1 2/2 3/1\n"),
                "texture coordinate index 2 is out of range (the file has 1 texture coordinates)");
  expectRefused(write("normal.obj", std::string(kTriangleObj) + "vn 0 0 1\nf 1//1 2//1 3//9\n"),
                "normal index 9 is out of range");
}

TEST_F(ReadBadInput, OffWithIndexOutOfRange)
{
  expectRefused(write("index.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n"),
                "face 1 refers to vertex 3, out of range (the file has 3 vertices)");
}

TEST_F(ReadBadInput, OffTruncatedOrGarbled)
{
  expectRefused(write("short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n"), "cannot read face 0");
  expectRefused(write("fewer.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n"),
                "cannot read the coordinates of vertex 3 (of 4)");
  expectRefused(write("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"),
                "cannot read the coordinates of vertex 1");
  expectRefused(write("counts.off", "OFF\nthree 1 0\n"), "cannot read the vertex, face and edge counts");
  expectRefused(write("header.off", "FOO\n3 1 0\n"), "not an OFF file");
  expectRefused(write("oneline.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                "counts must be on the line after 'OFF'");
  // Found by fuzzing (Testing/Fuzz/Findings/FuzzMeshReader-off): a header OpenMesh reads as ASCII
  // though it names BINARY, and binary counts the file cannot hold; OpenMesh allocated for both.
  expectRefused(write("binary-word.off", "OFF\x9f" "40-  BINARY"), "garbled OFF header");
  expectRefused(write("binary-counts.off", "OFFBINARY"),
                "cannot read the vertex, face and edge counts of the binary OFF file");
  expectRefused(write("binary-huge.off", std::string("OFF BINARY\n") + std::string(12, '\x7f')),
                "more than the file's");
}

TEST_F(ReadBadInput, EmptyFiles)
{
  for (const char* name : {"empty.obj", "empty.stl", "empty.ply", "empty.vtp", "empty.glb", "empty.off"})
  {
    expectRefused(write(name, ""), "the file is empty");
  }
}

TEST_F(ReadBadInput, MissingFileAndDirectory)
{
  expectRefused((m_dir / "missing.obj").string(), "cannot open the file (No such file or directory)");
  fs::create_directories(m_dir / "folder.stl");
  expectRefused((m_dir / "folder.stl").string(), "is a directory");
}

TEST_F(ReadBadInput, UnsupportedExtension)
{
  expectRefused(write("mesh.xyz", kTriangleObj), "unsupported file extension '.xyz'");
}

TEST_F(ReadBadInput, GarbageBytesInEveryFormat)
{
  const std::string bytes = garbage(2000);
  expectRefused(write("garbage.stl", bytes), "not a valid binary STL file");
  expectRefused(write("garbage.obj", bytes), "not an OBJ text file");
  expectRefused(write("garbage.ply", bytes), "not a PLY file");
  expectRefused(write("garbage.vtp", bytes), "not a VTK XML file");
  expectRefused(write("garbage.glb", bytes), "not a glTF file");
  expectRefused(write("garbage.off", bytes), "not an OFF file");
}

TEST_F(ReadBadInput, GarbageBehindARightLookingStart)
{
  // Past the magic words the readers' own errors must come through, as one line.
  expectRefused(write("body.vtp", "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\"><Poly"),
                "cannot read the file as VTK XML poly data");
  expectRefused(write("body.glb", "glTF" + garbage(100)), "cannot read the file as glTF");
  expectRefused(write("body.gltf", "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ { } ] "),
                "cannot read the file as glTF");
  expectRefused(write("body.ply", "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n"),
                "PLY element 'vertex' has no properties");
  expectRefused(write("noface.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                    "property float y\nproperty float z\nend_header\n0 0 0\n"),
                "no triangles (the PLY header has no face element");
  expectRefused(write("short.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"),
                "cannot read the file as STL");
}

TEST_F(ReadBadInput, BinaryStlTruncatedOrEmpty)
{
  std::string header(80, ' ');
  std::string stl = header;
  const std::uint32_t two = 2;
  stl.append(reinterpret_cast<const char*>(&two), 4);
  stl.append(50, '\0'); // one triangle of the two announced
  expectRefused(write("truncated.stl", stl), "announces 2 triangles");
  std::string none = header;
  const std::uint32_t zero = 0;
  none.append(reinterpret_cast<const char*>(&zero), 4);
  expectRefused(write("none.stl", none), "no triangles");
}

TEST_F(ReadBadInput, NanInAsciiStlAndPly)
{
  expectRefused(write("nan.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                 "vertex nan 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid x\n"),
                "point 1 has a non-finite coordinate (nan, 0, 0)");
  const std::string plyHeader = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n";
  expectRefused(write("nan.ply", plyHeader + "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n"),
                "point 1 has a non-finite coordinate (1, inf, 0)");
  // Found by fuzzing (Testing/Fuzz/Findings/FuzzMeshReader-ply): an ASCII list length far
  // beyond its uchar type sized the index buffer (2.7 GB) before a value was read.
  expectRefused(write("list-length.ply", plyHeader + "0 0 0\n1 0 0\n0 1 0\n333333333 0 1\n"),
                "list length 333333333 is more than the file has bytes left");
  expectRefused(write("index.ply", plyHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"),
                "face 0 refers to vertex 9, out of range (the file has 3 vertices)");
  expectRefused(write("word.ply", plyHeader + "0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n"),
                "PLY element 'vertex' item 1: cannot read 'x' as a number");
}

TEST_F(ReadBadInput, PlyCutShort)
{
  // A binary PLY of 1,000 vertices with its data cut in the vertex section, then in the faces.
  std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 1000\n"
                       "property float x\nproperty float y\nproperty float z\nelement face 2\n"
                       "property list uchar int vertex_indices\nend_header\n";
  expectRefused(write("vertices.ply", header + std::string(2000, '\0')),
                "PLY element 'vertex' item 166: the data ends early (truncated file)");
  std::string faces = header + std::string(12000, '\0');
  faces += '\3';
  faces += std::string(12, '\0');
  faces += '\3';
  faces += std::string(4, '\0');
  expectRefused(write("faces.ply", faces),
                "PLY element 'face' item 1: the data ends early (truncated file)");
  const std::string ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 1\n"
                            "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n";
  expectRefused(write("ascii.ply", ascii),
                "PLY element 'vertex' item 2: the data ends early (truncated file)");
  expectRefused(write("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                                  "property float x\nproperty float y\nproperty float z\n"
                                  "element face 1\nproperty list uchar int vertex_indices\n"
                                  "end_header\n" + std::string(64, '\0')),
                "more than the file's 64 bytes of data can hold");
}

TEST_F(ReadBadInput, OnlyLinesNoTriangles)
{
  expectRefused(write("lines.obj", std::string(kTriangleObj) + "l 1 2\nl 2 3\n"),
                "no triangles (only 2 lines and 0 vertex cells)");
  expectRefused(write("lines.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n2 1 2\n"), "no triangles");
  expectRefused(write("points.obj", "v 0 0 0\n"), "no triangles");
}

TEST_F(ReadBadInput, LoadTriangleMeshRefusesTheSameWay)
{
  const std::string path = write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  EXPECT_THROW((void)proxima::loadTriangleMesh(path), proxima::InputError);
}

TEST_F(ReadBadInput, PolygonsAreTriangulatedAndLinesIgnored)
{
  const proxima::TriangleSoup soup = proxima::readMeshFile(
    write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nl 1 3\n"));
  EXPECT_EQ(soup.triangles.size(), 2u);
  EXPECT_EQ(soup.points.size(), 4u);
  const proxima::TriangleSoup off = proxima::readMeshFile(
    write("pentagon.off", "OFF\n5 1 0\n0 0 0\n2 0 0\n2 1 0\n1 2 0\n0 1 0\n5 0 1 2 3 4\n"));
  EXPECT_EQ(off.triangles.size(), 3u);
}

TEST_F(ReadBadInput, OffBinaryAndNormalsAreRead)
{
  // "OFF BINARY": little-endian int32 counts, float32 coordinates, int32 face sizes and indices.
  std::string binary = "OFF BINARY\n";
  auto put = [&binary](auto value) {
    binary.append(reinterpret_cast<const char*>(&value), sizeof(value));
  };
  put(std::int32_t{3});
  put(std::int32_t{1});
  put(std::int32_t{0});
  for (float coordinate : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
  {
    put(coordinate);
  }
  for (std::int32_t value : {3, 0, 1, 2})
  {
    put(value);
  }
  const proxima::TriangleSoup soup = proxima::readMeshFile(write("binary.off", binary));
  ASSERT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.points[1], (proxima::Vec3{1, 0, 0}));
  // Cut short: the counts ask for more than the bytes left (refused before OpenMesh reads).
  expectRefused(write("cut.off", binary.substr(0, binary.size() - 6)), "more than the file's");

  const proxima::TriangleSoup normals = proxima::readMeshFile(
    write("normals.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"));
  ASSERT_EQ(normals.pointNormals.size(), 3u);
  EXPECT_EQ(normals.pointNormals[2], (proxima::Vec3{0, 0, 1}));
}

TEST_F(ReadBadInput, ObjNormalsAndTexCoordsArePerPoint)
{
  const proxima::TriangleSoup soup = proxima::readMeshFile(
    write("attributes.obj", std::string(kTriangleObj) +
                              "v 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvn 0 0 1\n"
                              "f 1/1/1 2/2/1 3/3/1\nf 2/2/1 4/4/1 3/3/1\n"));
  EXPECT_EQ(soup.triangles.size(), 2u);
  // One point per distinct (v, vt, vn) corner: the six corners share four.
  EXPECT_EQ(soup.points.size(), 4u);
  ASSERT_EQ(soup.pointNormals.size(), 4u);
  ASSERT_EQ(soup.texCoords.size(), 4u);
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    EXPECT_EQ(soup.pointNormals[i], (proxima::Vec3{0, 0, 1}));
    EXPECT_EQ(soup.texCoords[i].u, soup.points[i].x);
    EXPECT_EQ(soup.texCoords[i].v, soup.points[i].y);
  }
}
} // namespace
