// The token a server on a non-loopback address asks of its clients (Documentation/Server.md,
// "Security"): sent as the call's `proxima-token` metadata, compared in constant time.
#pragma once

#include <grpcpp/server_context.h>

#include <string>

namespace proxima::detail
{

/// True when `token` is empty (no token asked) or the call carries exactly it.
bool tokenAccepted(const grpc::ServerContext& context, const std::string& token);

/// The metadata key of the token.
inline constexpr const char* kTokenMetadata = "proxima-token";

} // namespace proxima::detail
