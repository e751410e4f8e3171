// VTP files whose declared sizes cannot be in their bytes are refused before VTK's XML reader
// allocates for them (issue 13: a 2 KB file declaring 900,000,000 points made it allocate
// 21.6 GB; a fuzzed compression header ran it out of memory). The oracle for what must still be
// read is VTK's own writer: every layout it writes (ASCII, inline binary, appended raw and
// base64; no compression, zlib, LZ4, LZMA; 32- and 64-bit headers) comes back whole.
#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/MeshReader.h"

#include "IO/Testing/ScratchFolderTest.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkXMLPolyDataWriter.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace
{
namespace fs = std::filesystem;

class ReadVtpSizes : public proxima::testing_support::ScratchFolderTest
{
protected:
  ReadVtpSizes()
    : ScratchFolderTest("proxima-vtp-")
  {}

  static std::string refusal(const std::string& path)
  {
    try
    {
      (void)proxima::readMeshFile(path);
    }
    catch (const proxima::InputError& error)
    {
      return error.what();
    }
    return "(read)";
  }
};

TEST_F(ReadVtpSizes, APieceDeclaringMorePointsThanTheFileCanHoldIsRefused)
{
  // 2 KB of ASCII declaring 900,000,000 points: about 2,000 values fit.
  std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n"
                     "<PolyData>\n<Piece NumberOfPoints=\"900000000\" NumberOfPolys=\"1\">\n"
                     "<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" "
                     "format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray>\n</Points>\n";
  text += "<!--" + std::string(2048 - text.size(), ' ') + "-->\n";
  text += "</Piece>\n</PolyData>\n</VTKFile>\n";
  const std::string message = refusal(write("many-points.vtp", text));
  EXPECT_NE(message.find("its pieces declare NumberOfPoints=\"900000000\", more than a file of"),
            std::string::npos)
    << message;
}

TEST_F(ReadVtpSizes, TheFuzzedCompressionHeaderIsRefused)
{
  const fs::path finding = fs::path(PROXIMA_SOURCE_DIR) / "Testing" / "Fuzz" / "Findings" /
                           "FuzzMeshReader-vtp" /
                           "FuzzMeshReader-vtp-oom-e6d607333207464346103c4810d946a3b56a0a04";
  std::ifstream in(finding, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(bytes.empty());
  const std::string message = refusal(write("finding.vtp", bytes));
  // Its Polys connectivity header: 2,570,787,840 blocks of 1,330,632,158 bytes.
  EXPECT_NE(message.find("compression header declares 2570787840 blocks"), std::string::npos)
    << message;
}

TEST_F(ReadVtpSizes, AnUncompressedArrayLongerThanTheFileIsRefused)
{
  // Inline binary without a compressor: a 4-byte count (base64 of 0xFFFFFF00) and 9 floats'
  // worth of text at most.
  const std::string text =
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
    "byte_order=\"LittleEndian\" header_type=\"UInt32\">\n<PolyData>\n"
    "<Piece NumberOfPoints=\"3\" NumberOfPolys=\"0\">\n<Points>\n<DataArray type=\"Float32\" "
    "NumberOfComponents=\"3\" format=\"binary\">AP///wAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA"
    "</DataArray>\n</Points>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  const std::string message = refusal(write("long-array.vtp", text));
  EXPECT_NE(message.find("DataArray 0 declares 4294967040 bytes of data"), std::string::npos)
    << message;
}

TEST_F(ReadVtpSizes, AnAppendedOffsetOutsideTheDataIsRefused)
{
  std::string text =
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n<PolyData>\n"
    "<Piece NumberOfPoints=\"1\" NumberOfPolys=\"0\">\n<Points>\n<DataArray type=\"Float32\" "
    "NumberOfComponents=\"3\" format=\"appended\" offset=\"99999\"/>\n</Points>\n</Piece>\n"
    "</PolyData>\n<AppendedData encoding=\"raw\">\n_\x0c";
  text += std::string(15, '\0'); // the rest of the count 12, then three zero floats
  text += "\n</AppendedData>\n</VTKFile>\n";
  const std::string message = refusal(write("offset.vtp", text));
  EXPECT_NE(message.find("offset \"99999\" is not inside the file's appended data"),
            std::string::npos)
    << message;
}

TEST_F(ReadVtpSizes, EveryLayoutVtkWritesIsStillRead)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(12);
  sphere->Update();
  const vtkIdType points = sphere->GetOutput()->GetNumberOfPoints();
  int written = 0;
  for (const int mode : {vtkXMLWriter::Ascii, vtkXMLWriter::Binary, vtkXMLWriter::Appended})
  {
    for (const int compressor :
         {vtkXMLWriter::NONE, vtkXMLWriter::ZLIB, vtkXMLWriter::LZ4, vtkXMLWriter::LZMA})
    {
      for (const bool encodeAppended : {false, true})
      {
        for (const bool wideHeader : {false, true})
        {
          const std::string name = "sphere-" + std::to_string(written++) + ".vtp";
          vtkNew<vtkXMLPolyDataWriter> writer;
          writer->SetInputData(sphere->GetOutput());
          writer->SetFileName(pathOf(name).c_str());
          writer->SetDataMode(mode);
          writer->SetCompressorType(compressor);
          writer->SetEncodeAppendedData(encodeAppended);
          writer->SetHeaderType(wideHeader ? vtkXMLWriter::UInt64 : vtkXMLWriter::UInt32);
          ASSERT_EQ(writer->Write(), 1) << name;
          const std::string context = name + " mode " + std::to_string(mode) + " compressor " +
                                      std::to_string(compressor) + " encoded " +
                                      std::to_string(encodeAppended) + " 64-bit header " +
                                      std::to_string(wideHeader);
          const proxima::TriangleSoup soup = proxima::readMeshFile(pathOf(name));
          EXPECT_EQ(static_cast<vtkIdType>(soup.points.size()), points) << context;
          EXPECT_EQ(static_cast<vtkIdType>(soup.triangles.size()),
                    sphere->GetOutput()->GetNumberOfPolys())
            << context;
        }
      }
    }
  }
}

} // namespace
