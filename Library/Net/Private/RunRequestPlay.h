// One remote run as the server plays it, apart from the network: the request checked and decoded
// (its settings into ScriptedRunSettings, its files written into a folder of the run's own), the
// path played in lockstep, the ticks handed to `write` in chunks and the summary last. The gRPC
// service calls it after checking the token, and the fuzz target FuzzRunRequest calls it on
// requests decoded from random bytes (Documentation/Fuzzing.md).
#pragma once

#include "proxima_remote.pb.h"

#include <grpcpp/support/status.h>

#include <functional>

namespace proxima
{

/// What the server allows one run.
struct RunLimits
{
  /// The most ticks one run may take: a run's own limit (its settings' max_ticks, the client's
  /// --max-ticks) is taken within it, and a path that needs more is refused before it is played,
  /// as `proxima run --max-ticks` refuses it.
  double maxTicks = 1e7;
};

/// Plays `request`; `write` sends one reply (false when the client went away), `cancelled` says
/// whether the client cancelled. Bad input ends with INVALID_ARGUMENT and the one-line message a
/// local run would print, about the client's file names.
grpc::Status playRunRequest(const net::RunRequest& request, const RunLimits& limits,
                            const std::function<bool(const net::RunReply&)>& write,
                            const std::function<bool()>& cancelled);

} // namespace proxima
