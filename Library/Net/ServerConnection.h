// How a client reaches a Proxima server (Documentation/Server.md): its address, the token a
// server on a non-loopback address asks for, for a server with TLS credentials the certificates
// that sign its certificate, and how long a client waits for a server that went away to come
// back. Both clients take it: remote runs (RemoteRuns.h) and the live client (HapticClient.h).
#pragma once

#include <chrono>
#include <string>

namespace proxima
{

/// How a client rides out a server that goes away and comes back on the same address (a restart,
/// a dropped connection): a call that fails because the server is unavailable is made again once
/// gRPC has the connection back. gRPC reconnects by itself, `firstBackoff` after the failure and
/// then at intervals growing by its factor of 1.6 up to `maxBackoff`; the client waits for the
/// connection (not a fixed time) and gives up `maxWait` after the first failure, with an error
/// naming the address. The first connection is not retried: an address where nothing has ever
/// answered is an error at once (ServerChannel.h).
struct ReconnectPolicy
{
  std::chrono::milliseconds firstBackoff{50};
  std::chrono::milliseconds maxBackoff{2000};
  /// Zero: a call that fails is an error at once, as before clients reconnected.
  std::chrono::milliseconds maxWait{10000};
};

struct ServerConnection
{
  /// HOST:PORT.
  std::string server;
  /// Sent with every call; empty for none.
  std::string token;
  /// PEM root certificates that sign the server's certificate (`proxima remote --tls-ca`):
  /// the channel is TLS, and the server's name must match its certificate. Empty: a plain
  /// channel.
  std::string tlsRootCertificates;
  /// `proxima remote --reconnect SECONDS` sets maxWait.
  ReconnectPolicy reconnect = {};
};

} // namespace proxima
