// How a client reaches a Proxima server (Documentation/Server.md): its address, the token a
// server on a non-loopback address asks for, for a server with TLS credentials the certificates
// that sign its certificate, and how long a client waits for a server that went away to come
// back. Both clients take it: remote runs (RemoteRuns.h) and the live client (HapticClient.h).
#pragma once

#include "IO/InputChecks/InputError.h"

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
  /// How long after the connection drops gRPC first tries to connect again (at least 1 ms).
  std::chrono::milliseconds firstBackoff{50};
  /// The longest interval between gRPC's tries to connect again (at least firstBackoff).
  std::chrono::milliseconds maxBackoff{2000};
  /// How long after the first failure the client waits for the server before it gives up. Zero:
  /// a call that fails is an error at once.
  std::chrono::milliseconds maxWait{10000};
};

/// Where and how a client reaches a Proxima server: its address, token, TLS roots and
/// reconnection policy. HapticClient and runRemotely take it.
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
  /// How long the first connection may take before nothing answering there is an error (a
  /// refused connection is one at once).
  std::chrono::milliseconds connectTimeout{10000};
};

/// The server cannot be reached: nothing answers at its address, it went away and did not come
/// back within the ReconnectPolicy, or it is not a server of the kind asked for (no device). An
/// InputError naming --server, so that a caller that only reports errors needs nothing new; a
/// caller that retries, or a binding that maps it (Python's ConnectionError), can tell it apart.
class ServerUnavailable : public InputError
{
public:
  /// An error about `path` (--server) with `defect` in words, as InputError's.
  using InputError::InputError;
};

/// The server refused this client what it asked: another client owns the model, or the token is
/// wrong or missing. An InputError naming --server or --token-file (Python's PermissionError).
class ServerRefused : public InputError
{
public:
  /// An error about `path` (--server or --token-file) with `defect` in words, as InputError's.
  using InputError::InputError;
};

} // namespace proxima
