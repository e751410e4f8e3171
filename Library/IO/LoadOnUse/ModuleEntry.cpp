#include "IO/LoadOnUse/ModuleEntry.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace proxima::detail
{

void* moduleEntry(const char* modulePath, const char* entry)
{
  // RTLD_LOCAL: the module's copies of our own code stay its own (it is linked -Bsymbolic too).
  void* module = dlopen(modulePath, RTLD_NOW | RTLD_LOCAL);
  if (!module)
  {
    const char* reason = dlerror();
    throw std::runtime_error(std::string("cannot load the module ") + modulePath + ": " +
                             (reason ? reason : "unknown reason"));
  }
  void* address = dlsym(module, entry);
  if (!address)
  {
    throw std::runtime_error(std::string("the module ") + modulePath + " has no entry " + entry);
  }
  return address;
}

} // namespace proxima::detail
