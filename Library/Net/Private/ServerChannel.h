// The channel to a Proxima server, connected before any call: a refused connection is known at
// once rather than retried until a deadline (both clients: remote runs and the live client). Once
// connected, the channel reconnects by itself with the backoff of the connection's
// ReconnectPolicy, and Reconnection waits for it after a call failed because the server went away.
#pragma once

#include "Net/ServerConnection.h"

#include <grpcpp/channel.h>

#include <chrono>
#include <memory>
#include <string>

namespace proxima::detail
{

/// A ready channel to `connection.server` (HOST:PORT), over TLS when it gives root certificates,
/// whose messages may be of any size, and which reconnects with `connection.reconnect`'s backoff.
/// Throws InputError naming --server when nothing answers there (at once when the connection is
/// refused or the TLS handshake fails, after 10 s when it never answers).
std::shared_ptr<grpc::Channel> connectToServer(const ServerConnection& connection);

/// One client's wait for a server that went away (a call failed with UNAVAILABLE) to come back:
/// the wait is on the channel's connectivity (gRPC reconnects with its backoff), bounded by the
/// policy's maxWait from the first failure until a call goes through again. Not thread-safe: one
/// per thread that makes calls.
class Reconnection
{
public:
  Reconnection(const ServerConnection& connection, grpc::Channel& channel);
  /// A call failed with UNAVAILABLE: the wait starts at the first failure. False when the policy
  /// gives up (it never retries, or its maxWait has passed).
  bool failed();
  /// After failed(): waits until the channel is connected again (true) or the deadline passes
  /// (false: give up).
  bool waitForServer();
  /// After failed(), for a caller that waits on a call of its own (wait_for_ready): when the
  /// channel still looks ready (a server that is closing its connection refused the call), waits
  /// for it to change, at most until the next backoff (50 ms doubling to the policy's maximum).
  void pauseWhileReady();
  /// A call went through: the next failure starts a new wait.
  void succeeded() { m_waiting = false; }
  /// Whether a wait is under way (a call failed and none has gone through since).
  bool waiting() const { return m_waiting; }
  /// When this wait gives up (meaningful while waiting()).
  std::chrono::system_clock::time_point deadline() const { return m_deadline; }
  /// How many times a call failed and was made again, so far.
  unsigned retries() const { return m_retries; }
  /// The one-line message of giving up, for InputError("--server", ...): the address, how long
  /// it waited, and the last call's error.
  std::string gaveUp(const std::string& lastError) const;

private:
  ReconnectPolicy m_policy;
  std::string m_server;
  grpc::Channel& m_channel;
  bool m_waiting = false;
  std::chrono::system_clock::time_point m_deadline;
  std::chrono::milliseconds m_backoff{0};
  unsigned m_retries = 0;
};

} // namespace proxima::detail
