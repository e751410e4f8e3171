#include "Net/Private/RunFolder.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/InputChecks/InputError.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace proxima::detail
{
namespace fs = std::filesystem;

namespace
{
bool lettersAndDigits(const std::string& text, std::size_t from)
{
  return std::all_of(text.begin() + static_cast<std::ptrdiff_t>(from), text.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; });
}

// "file<K>" with an optional ".<letters and digits>": what packSceneFile names bundled files,
// and nothing that could leave the folder.
bool bundledName(const std::string& name)
{
  const std::size_t dot = name.find('.');
  const std::string stem = name.substr(0, dot);
  if (stem.size() < 5 || stem.compare(0, 4, "file") != 0 || stem.size() > 14)
  {
    return false;
  }
  for (std::size_t i = 4; i < stem.size(); ++i)
  {
    if (!std::isdigit(static_cast<unsigned char>(stem[i])))
    {
      return false;
    }
  }
  return dot == std::string::npos || (name.size() > dot + 1 && lettersAndDigits(name, dot + 1));
}
} // namespace

RunFolder::RunFolder()
{
  std::string pattern = (fs::temp_directory_path() / "proxima-remote-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr)
  {
    throw std::runtime_error("cannot make a folder for the run's files");
  }
  m_path = pattern;
}

RunFolder::~RunFolder()
{
  std::error_code ignored;
  fs::remove_all(m_path, ignored);
}

std::string RunFolder::write(const std::string& clientName, const std::string& data,
                             const std::string& stem)
{
  std::string extension = fs::path(clientName).extension().string();
  if (!lettersAndDigits(extension, std::min<std::size_t>(1, extension.size())))
  {
    extension.clear();
  }
  return writeAs(stem + extension, data, clientName);
}

std::string RunFolder::writeScene(const net::SceneBundle& bundle)
{
  for (const net::BundledFile& file : bundle.files())
  {
    if (!bundledName(file.local_name()) || file.local_name().size() > 40)
    {
      throw InputError(bundle.scene_name(),
                       "the upload names a bundled file '" + file.local_name().substr(0, 40) +
                         "', which is not a name a Proxima client gives (file<K>.<ext>)");
    }
    if (fs::exists(m_path / file.local_name()))
    {
      throw InputError(bundle.scene_name(), "the upload bundles '" + file.local_name() + "' twice");
    }
    writeAs(file.local_name(), file.data(), file.client_name());
  }
  m_sceneName = bundle.scene_name();
  return writeAs("scene.json", bundle.scene_json(), bundle.scene_name());
}

void RunFolder::requireBundledFiles(const SceneDescription& description) const
{
  const auto require = [this](const std::string& path) {
    std::error_code ignored;
    const fs::path file = fs::weakly_canonical(path, ignored);
    const bool bundled = file.parent_path() == fs::weakly_canonical(m_path, ignored) &&
                         bundledName(file.filename().string()) && fs::exists(file, ignored);
    if (!bundled)
    {
      throw InputError(m_sceneName, "names '" + path.substr(0, 200) +
                                      "', which is not a file of the upload: a scene sent to a "
                                      "server names only the files sent with it");
    }
  };
  for (const SceneObject& object : description.objects)
  {
    require(object.mesh);
    for (const SceneTexture& texture : object.material.textures)
    {
      require(texture.image);
    }
  }
  if (!description.mjcf.empty())
  {
    require(description.mjcf);
    const std::string text = readWholeFile(description.mjcf, "MJCF file");
    if (text.find("file=") != std::string::npos || text.find("file =") != std::string::npos)
    {
      throw InputError(m_sceneName, "its MJCF file names files of its own (file=...), which a "
                                    "scene sent to a server cannot: its mechanism must be made "
                                    "of the scene's meshes and MuJoCo's own shapes");
    }
  }
}

std::string RunFolder::writeAs(const std::string& localName, const std::string& data,
                               const std::string& clientName)
{
  const std::string local = (m_path / localName).string();
  std::ofstream out(local, std::ios::binary);
  out.write(data.data(), static_cast<std::streamsize>(data.size()));
  out.close();
  if (!out)
  {
    throw std::runtime_error("cannot write the run's files on the server");
  }
  m_names.emplace_back(local, clientName);
  return local;
}

std::string RunFolder::clientWords(std::string text) const
{
  // Longest local paths first, so that no path is replaced inside a longer one.
  std::vector<std::pair<std::string, std::string>> names = m_names;
  std::sort(names.begin(), names.end(),
            [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
  for (const auto& [local, client] : names)
  {
    for (std::size_t at = text.find(local); at != std::string::npos;
         at = text.find(local, at + client.size()))
    {
      text.replace(at, local.size(), client);
    }
  }
  return text;
}

} // namespace proxima::detail
