#include "IO/Mesh/Private/VtkReaders.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/Private/VtkMessageCapture.h"

#include <vtkAppendPolyData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkGLTFReader.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkXMLPolyDataReader.h>

namespace proxima::detail
{
namespace
{
bool isEmpty(vtkPolyData* data)
{
  return data == nullptr || (data->GetNumberOfPoints() == 0 && data->GetNumberOfCells() == 0);
}

/// `text` with every occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to)
{
  for (std::size_t at = text.find(from); !from.empty() && at != std::string::npos;
       at = text.find(from, at + to.size()))
  {
    text.replace(at, from.size(), to);
  }
  return text;
}

/// Fails loudly where VTK failed quietly: an error message, or a warning with nothing read.
/// `readPath` is the file VTK read, named in its messages as `path` when it is a copy.
void throwIfFailed(const std::string& path, const VtkMessageCapture& capture, bool producedNothing,
                   const char* formatName, const std::string& readPath = std::string())
{
  if (capture.hasErrors() || (producedNothing && !capture.messages().empty()))
  {
    throw InputError(path, std::string("cannot read the file as ") + formatName + " (" +
                             replaced(capture.bestMessage(), readPath, path) + ")");
  }
}

template <class Reader>
vtkSmartPointer<vtkPolyData> readSingle(const std::string& path, const char* formatName)
{
  VtkMessageCapture capture;
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> output = reader->GetOutput();
  throwIfFailed(path, capture, isEmpty(output), formatName);
  if (reader->GetErrorCode() != 0)
  {
    throw InputError(path, std::string("cannot read the file as ") + formatName +
                             " (VTK error code " + std::to_string(reader->GetErrorCode()) + ")");
  }
  return output;
}

vtkSmartPointer<vtkPolyData> readGltf(const std::string& vtkPath, const std::string& path)
{
  VtkMessageCapture capture;
  vtkNew<vtkGLTFReader> reader;
  reader->SetFileName(vtkPath.c_str());
  // The reader places every mesh by its node's global transform (and applies skins and morph
  // targets at time 0 with deformations on): the model as its author laid it out.
  reader->ApplyDeformationsToGeometryOn();
  reader->Update();
  vtkMultiBlockDataSet* blocks = reader->GetOutput();
  vtkNew<vtkAppendPolyData> append;
  std::size_t numBlocks = 0;
  if (blocks)
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(blocks->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* part = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        append->AddInputData(part);
        ++numBlocks;
      }
    }
  }
  throwIfFailed(path, capture, numBlocks == 0, "glTF", vtkPath);
  if (numBlocks == 0)
  {
    throw InputError(path, "no triangles (the glTF scene has no meshes)");
  }
  // Arrays every part has (normals, texture coordinates) survive the append; others are dropped.
  append->Update();
  throwIfFailed(path, capture, false, "glTF", vtkPath);
  vtkSmartPointer<vtkPolyData> merged = append->GetOutput();
  return merged;
}
} // namespace

vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, MeshFileFormat format)
{
  switch (format)
  {
    case MeshFileFormat::Stl: return readSingle<vtkSTLReader>(path, "STL");

    case MeshFileFormat::Vtp: return readSingle<vtkXMLPolyDataReader>(path, "VTK XML poly data");
    case MeshFileFormat::Gltf: // only its checked copy, through readGltfWithVtk
    case MeshFileFormat::Obj:
    case MeshFileFormat::Ply:
    case MeshFileFormat::Off: break; // our own readers, see MeshReader.cpp
  }
  throw InputError(path, "internal: this format is not read through VTK");
}

vtkSmartPointer<vtkPolyData> readGltfWithVtk(const std::string& vtkPath,
                                             const std::string& userPath)
{
  return readGltf(vtkPath, userPath);
}

} // namespace proxima::detail
