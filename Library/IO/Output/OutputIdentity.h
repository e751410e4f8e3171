// Outputs that must not be one of the run's inputs, nor one another: `path slide --mesh a.obj
// --out a.obj` would replace the mesh, `--out t.csv --summary t.csv` would lose the trace.
// Compared by the file system's identity, not by spelling ("./a.obj", a link to it).
#pragma once

#include <string>
#include <vector>

namespace proxima
{

/// A file a command reads or writes, and what names it on the command line ("--mesh", "the
/// scene's objects[1]").
struct NamedFile
{
  /// The path as given; empty when the option was not given (the file is then skipped).
  std::string path;
  /// What names the file in messages: the option or the scene key.
  std::string role;
};

/// True when `a` and `b` are the same regular file: the same device and inode when both exist,
/// otherwise the same absolute, normal path (std::filesystem::weakly_canonical, which resolves
/// the links of what exists). Devices and pipes never count: writing /dev/null twice is fine.
bool namesSameFile(const std::string& a, const std::string& b);

/// Throws OutputError naming the output when one of `outputs` is one of `inputs` or two outputs
/// are one file. Empty paths (options not given) are skipped.
void refuseOverlappingFiles(const std::vector<NamedFile>& outputs,
                            const std::vector<NamedFile>& inputs);

} // namespace proxima
