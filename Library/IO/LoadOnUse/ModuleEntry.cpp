#include "IO/LoadOnUse/ModuleEntry.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace proxima::detail
{
namespace
{
// The folders moduleFolder looks in, in order (see ModuleEntry.h).
std::vector<std::string> moduleFolders()
{
  std::vector<std::string> folders;
  if (const char* fromEnvironment = std::getenv("PROXIMA_MODULE_DIR"))
  {
    folders.emplace_back(fromEnvironment);
  }
  if (&proxima_installed_module_dir != nullptr && proxima_installed_module_dir != nullptr)
  {
    folders.emplace_back(proxima_installed_module_dir);
  }
  std::string program(4096, '\0');
  const ssize_t length = readlink("/proc/self/exe", program.data(), program.size());
  if (length > 0 && static_cast<std::size_t>(length) < program.size())
  {
    program.resize(static_cast<std::size_t>(length));
    const std::size_t slash = program.rfind('/');
    if (slash != std::string::npos)
    {
      folders.push_back(program.substr(0, slash) + "/../lib/proxima");
    }
  }
  folders.emplace_back(PROXIMA_BUILD_MODULE_DIR);
  folders.emplace_back(PROXIMA_INSTALL_MODULE_DIR);
  return folders;
}

bool isFile(const std::string& path)
{
  struct stat status
  {};
  return stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode);
}
} // namespace

std::string moduleFolder(const char* fileName)
{
  for (const std::string& folder : moduleFolders())
  {
    if (isFile(folder + "/" + fileName))
    {
      return folder;
    }
  }
  return {};
}

void* moduleEntry(const char* fileName, const char* entry)
{
  const std::string folder = moduleFolder(fileName);
  if (folder.empty())
  {
    std::string places;
    for (const std::string& tried : moduleFolders())
    {
      places += (places.empty() ? "" : ", ") + tried;
    }
    throw std::runtime_error(std::string("cannot find the module ") + fileName + " (looked in " +
                             places + "; set PROXIMA_MODULE_DIR to the folder that has it)");
  }
  const std::string path = folder + "/" + fileName;
  // RTLD_LOCAL: the module's copies of our own code stay its own (it is linked -Bsymbolic too).
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!module)
  {
    const char* reason = dlerror();
    throw std::runtime_error("cannot load the module " + path + ": " +
                             (reason ? reason : "unknown reason"));
  }
  void* address = dlsym(module, entry);
  if (!address)
  {
    throw std::runtime_error("the module " + path + " has no entry " + entry);
  }
  return address;
}

} // namespace proxima::detail
