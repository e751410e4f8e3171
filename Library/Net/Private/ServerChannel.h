// The channel to a Proxima server, connected before any call: a refused connection is known at
// once rather than retried until a deadline (both clients: remote runs and the live client).
#pragma once

#include "Net/ServerConnection.h"

#include <grpcpp/channel.h>

#include <memory>
#include <string>

namespace proxima::detail
{

/// A ready channel to `connection.server` (HOST:PORT), over TLS when it gives root certificates,
/// whose messages may be of any size. Throws InputError naming --server when nothing answers
/// there (at once when the connection is refused or the TLS handshake fails, after 10 s when it
/// never answers).
std::shared_ptr<grpc::Channel> connectToServer(const ServerConnection& connection);

} // namespace proxima::detail
