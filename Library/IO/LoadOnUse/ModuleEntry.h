// Parts of IO that need a heavy third-party package (VTK's STL, VTP and glTF readers, which pull
// in VTK's rendering; OpenImageIO, which pulls in some 260 shared libraries of codecs) are built
// as modules and loaded on first use, so that a program which never reads such a file does not
// load and relocate them at start-up (`proxima run` on an OBJ mesh, `proxima --help`). Plain C++.
#pragma once

#include <string>

/// Set by a program built against an installed Proxima (ProximaConfig.cmake compiles it into the
/// program): the folder the package's modules were installed to, wherever the package was
/// installed or moved. Weak: programs of the build tree do not define it.
extern "C" __attribute__((weak)) const char* const proxima_installed_module_dir;

namespace proxima::detail
{

/// The folder holding the module file `fileName`: the first of $PROXIMA_MODULE_DIR, the folder of
/// an installed package (proxima_installed_module_dir), ../lib/proxima beside the running program
/// (the installed tools, and the build tree's bin/), the build tree's lib/proxima and the
/// configured install prefix's, that has it. Empty when none has.
std::string moduleFolder(const char* fileName);

/// The address of the function `entry` in the module file `fileName` (found by moduleFolder),
/// loading the module the first time (dlopen; the module stays loaded). Throws
/// std::runtime_error, which callers report as an internal error, naming the module, the places
/// looked in and the loader's reason when it cannot be loaded or has no such entry: a build or an
/// installation whose modules are missing, not a defect of the user's file.
void* moduleEntry(const char* fileName, const char* entry);

} // namespace proxima::detail
