// Who may change the live server's model (proxima_haptic.proto's HoldOwnership): one client at a
// time holds a random key for as long as its call stays open; while one does, only uploads that
// carry that key are taken. The others observe. A key that is not the owner's is refused. Any
// thread.
#pragma once

#include <grpcpp/server_context.h>

#include <chrono>
#include <mutex>
#include <string>

namespace proxima::detail
{

class ModelOwnership
{
public:
  /// Makes `peer` the owner and returns its key, or returns empty and says in `holder` who owns
  /// the model (its address and for how long).
  std::string claim(const std::string& peer, std::string& holder);
  /// Ends the ownership of `key` (nothing if it no longer owns).
  void release(const std::string& key);
  /// Whether a call may change the model.
  enum class Right
  {
    /// No client owns the model and the call names no owner's key, or it carries the owner's.
    Granted,
    /// Another client owns the model and the call carries no key.
    OwnedByAnother,
    /// The call carries a key that is not the owner's: its ownership ended (its call dropped, or
    /// this server is a restart that never granted it). Refused even when nobody owns the model,
    /// so that a client that believes it owns the model learns that it does not.
    OwnershipEnded
  };
  Right mayChange(const grpc::ServerContext& context) const;

private:
  mutable std::mutex m_mutex;
  std::string m_key;
  std::string m_peer;
  std::chrono::steady_clock::time_point m_since;
};

} // namespace proxima::detail
