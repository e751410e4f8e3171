// The live haptic service (proxima_haptic.proto's HapticServer): clients upload models into the
// threaded runtime the server owns, and follow its state. An upload is assembled and its sphere
// trees built on the call's own thread; the runtime gets the scene only when it is whole and
// committed (publishScene: the proxy loop swaps it in at its next tick and never waits), so a
// client that dies mid-upload leaves the old model in place. A state stream reads the runtime's
// latest state, lock-free, at the rate its client asked for and never makes the haptic threads
// wait: a client that reads slowly loses samples, counted.
#pragma once

#include "Net/Private/ModelAssembly.h"
#include "Proxy/ProxyParameters.h"
#include "Runtime/ThreadedRuntime.h"

#include "proxima_haptic.grpc.pb.h"

#include <atomic>
#include <mutex>
#include <string>

namespace proxima::detail
{

class LiveHapticService final : public net::HapticServer::Service
{
public:
  LiveHapticService(ThreadedRuntime& runtime, const ProxyParameters& proxy, std::string token,
                    const ModelLimits& limits)
    : m_runtime(runtime)
    , m_proxy(proxy)
    , m_token(std::move(token))
    , m_limits(limits)
  {}

  grpc::Status UploadModel(grpc::ServerContext* context,
                           grpc::ServerReader<net::ModelUpload>* reader,
                           net::ModelReceipt* receipt) override;
  grpc::Status StreamState(grpc::ServerContext* context, const net::StateRequest* request,
                           grpc::ServerWriter<net::StateSample>* writer) override;

  /// Ends the state streams (before the server shuts down, which waits for its calls).
  void stop() { m_stopping = true; }

private:
  ThreadedRuntime& m_runtime;
  ProxyParameters m_proxy;
  std::string m_token;
  ModelLimits m_limits;
  /// One model is published at a time, so that versions go in commit order.
  std::mutex m_publishing;
  std::atomic<bool> m_stopping{false};
};

} // namespace proxima::detail
