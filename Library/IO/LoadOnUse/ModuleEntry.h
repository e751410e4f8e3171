// Parts of IO that need a heavy third-party package (VTK's STL, VTP and glTF readers, which pull
// in VTK's rendering; OpenImageIO, which pulls in some 260 shared libraries of codecs) are built
// as modules and loaded on first use, so that a program which never reads such a file does not
// load and relocate them at start-up (`proxima run` on an OBJ mesh, `proxima --help`). Plain C++.
#pragma once

namespace proxima::detail
{

/// The address of the function `entry` in the module at `modulePath`, loading the module the
/// first time (dlopen; the module stays loaded). Throws std::runtime_error, which callers report
/// as an internal error, naming the module and the loader's reason when it cannot be loaded or
/// has no such entry: a build whose modules are missing, not a defect of the user's file.
void* moduleEntry(const char* modulePath, const char* entry);

} // namespace proxima::detail
