// The token a server on a non-loopback address asks of its clients (Documentation/Server.md,
// "Security"): sent as the call's `proxima-token` metadata, compared in constant time; the model
// owner's key goes the same way.
#pragma once

#include <grpcpp/server_context.h>

#include <string>

namespace proxima::detail
{

/// True when `token` is empty (no token asked) or the call carries exactly it.
bool tokenAccepted(const grpc::ServerContext& context, const std::string& token);

/// True when the call's metadata `key` is exactly `expected` (compared in constant time).
bool metadataEquals(const grpc::ServerContext& context, const char* key,
                    const std::string& expected);

/// The metadata key of the token.
inline constexpr const char* kTokenMetadata = "proxima-token";
/// The metadata key of the model owner's key (proxima_haptic.proto's HoldOwnership).
inline constexpr const char* kOwnerMetadata = "proxima-owner";

} // namespace proxima::detail
