// libFuzzer target: one mesh reader (the extension is PROXIMA_FUZZ_EXTENSION, one executable per
// format) fed arbitrary bytes through a file, as a user's file would reach it. Bad input must come
// back as an InputError naming the file; anything else (a crash, a sanitizer report, another
// exception, a mesh that the kernel's build refuses after the reader accepted it) is a finding.
#include "FuzzScratchFile.h"

#include "IO/Mesh/MeshReader.h"

#include <cstdint>
#include <cstdlib>
#include <cstdio>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const proxima::fuzz::ScratchFile file(PROXIMA_FUZZ_EXTENSION);
  file.write(data, size);
  try
  {
    const proxima::TriangleMesh mesh = proxima::loadTriangleMesh(file.path());
    if (mesh.numTriangles() == 0)
    {
      std::fprintf(stderr, "a mesh without triangles was accepted\n");
      std::abort();
    }
  }
  catch (const proxima::InputError&)
  {
    // Refused with a message: what bad input should get.
  }
  return 0;
}
