// The channel to a Proxima server, connected before any call: a refused connection is known at
// once rather than retried until a deadline (both clients: remote runs and the live client).
#pragma once

#include <grpcpp/channel.h>

#include <memory>
#include <string>

namespace proxima::detail
{

/// A ready channel to `server` (HOST:PORT) whose messages may be of any size. Throws InputError
/// naming --server when nothing answers there (at once when the connection is refused, after 10 s
/// when it never answers).
std::shared_ptr<grpc::Channel> connectToServer(const std::string& server);

} // namespace proxima::detail
