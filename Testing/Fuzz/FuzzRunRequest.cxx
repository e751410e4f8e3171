// FuzzRunRequest: the server's decode and validation path (issue 16). Random bytes decoded as a
// RunRequest, as gRPC decodes what a client sends, then played as `proxima serve` plays it (its
// settings checked, its files written and read, the path run in lockstep), with a tick limit of
// 2,000 so that every input ends quickly. Every input must end with a status: no crash, hang or
// leak.
#include "Net/Private/RunRequestPlay.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  proxima::net::RunRequest request;
  if (!request.ParseFromArray(data, static_cast<int>(size)))
  {
    return 0;
  }
  proxima::RunLimits limits;
  limits.maxTicks = 2000;
  proxima::playRunRequest(
    request, limits, [](const proxima::net::RunReply&) { return true; }, [] { return false; });
  return 0;
}
