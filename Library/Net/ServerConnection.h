// How a client reaches a Proxima server (Documentation/Server.md): its address, the token a
// server on a non-loopback address asks for, and, for a server with TLS credentials, the
// certificates that sign its certificate. Both clients take it: remote runs (RemoteRuns.h) and
// the live client (HapticClient.h).
#pragma once

#include <string>

namespace proxima
{

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
};

} // namespace proxima
