// libFuzzer target: the scene file parser (IO/SceneFile.h) on arbitrary bytes. It reads no mesh,
// so this is the JSON and the format's checks alone; bad input must be an InputError.
#include "FuzzScratchFile.h"

#include "IO/Scene/SceneFile.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const proxima::fuzz::ScratchFile file(".json");
  file.write(data, size);
  try
  {
    (void)proxima::readSceneFile(file.path());
  }
  catch (const proxima::InputError&)
  {}
  return 0;
}
