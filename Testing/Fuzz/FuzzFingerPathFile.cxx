// libFuzzer target: the finger path parser (IO/FingerPathFile.h) on arbitrary bytes. What it
// accepts must keep its contract: at least one row, finite values, times that never go back.
#include "FuzzScratchFile.h"

#include "IO/PathAndTrace/FingerPathFile.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const proxima::fuzz::ScratchFile file(".csv");
  file.write(data, size);
  try
  {
    const proxima::FingerPath path = proxima::readFingerPathFile(file.path());
    bool good = !path.empty() && path.times.size() == path.positions.size();
    for (std::size_t i = 0; good && i < path.size(); ++i)
    {
      good = std::isfinite(path.times[i]) && proxima::isFinite(path.positions[i]) &&
             (i == 0 || path.times[i] >= path.times[i - 1]);
    }
    if (!good)
    {
      std::fprintf(stderr, "the path file was accepted but breaks the path contract\n");
      std::abort();
    }
  }
  catch (const proxima::InputError&)
  {}
  return 0;
}
