#include "IO/Mesh/MeshFileFormat.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace proxima
{

std::optional<MeshFileFormat> meshFileFormatFromPath(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".stl")
  {
    return MeshFileFormat::Stl;
  }
  if (extension == ".obj")
  {
    return MeshFileFormat::Obj;
  }
  if (extension == ".ply")
  {
    return MeshFileFormat::Ply;
  }
  if (extension == ".vtp")
  {
    return MeshFileFormat::Vtp;
  }
  if (extension == ".gltf" || extension == ".glb")
  {
    return MeshFileFormat::Gltf;
  }
  if (extension == ".off")
  {
    return MeshFileFormat::Off;
  }
  return std::nullopt;
}

std::string readableMeshExtensions()
{
  return ".stl, .obj, .ply, .vtp, .gltf, .glb, .off";
}

const char* meshFileFormatName(MeshFileFormat format)
{
  switch (format)
  {
    case MeshFileFormat::Stl: return "stl";
    case MeshFileFormat::Obj: return "obj";
    case MeshFileFormat::Ply: return "ply";
    case MeshFileFormat::Vtp: return "vtp";
    case MeshFileFormat::Gltf: return "gltf";
    case MeshFileFormat::Off: return "off";
  }
  return "unknown";
}

} // namespace proxima
