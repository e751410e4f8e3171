// The live haptic service (proxima_haptic.proto's HapticServer): clients upload models into the
// threaded runtime the server owns, and follow its state. An upload is assembled and its sphere
// trees built on the call's own thread; the runtime gets the scene only when it is whole and
// committed (publishScene: the proxy loop swaps it in at its next tick and never waits), so a
// client that dies mid-upload leaves the old model in place. A state stream reads the runtime's
// latest state, lock-free, at the rate its client asked for and never makes the haptic threads
// wait: a client that reads slowly loses samples, counted. One client at a time may own the model
// (ModelOwnership); the others observe.
#pragma once

#include "Net/Private/ModelAssembly.h"
#include "Net/Private/ModelOwnership.h"
#include "Proxy/ProxyParameters.h"
#include "Runtime/ThreadedRuntime.h"

#include "proxima_haptic.grpc.pb.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>

namespace proxima::detail
{

class LiveHapticService final : public net::HapticServer::Service
{
public:
  /// `stiffness` and `rate` are the servo's kp (N/m) and rate (Hz), which a scene's bodies are
  /// coupled at.
  LiveHapticService(ThreadedRuntime& runtime, const ProxyParameters& proxy, double stiffness,
                    double rate, std::string token, const ModelLimits& limits)
    : m_runtime(runtime)
    , m_proxy(proxy)
    , m_stiffness(stiffness)
    , m_rate(rate)
    , m_token(std::move(token))
    , m_limits(limits)
  {}

  grpc::Status UploadModel(grpc::ServerContext* context,
                           grpc::ServerReader<net::ModelUpload>* reader,
                           net::ModelReceipt* receipt) override;
  grpc::Status StreamState(grpc::ServerContext* context, const net::StateRequest* request,
                           grpc::ServerWriter<net::StateSample>* writer) override;
  grpc::Status HoldOwnership(
    grpc::ServerContext* context,
    grpc::ServerReaderWriter<net::OwnershipGrant, net::OwnershipRequest>* stream) override;

  /// Ends the state streams (before the server shuts down, which waits for its calls).
  void stop() { m_stopping = true; }

private:
  /// What one commit makes: the scene, its bodies (null for none) and its counts.
  struct BuiltModel
  {
    std::shared_ptr<CollisionScene> scene;
    std::shared_ptr<TickDynamics> dynamics;
    std::uint32_t shapes = 0;
    std::uint64_t triangles = 0;
  };
  /// A scene bundle read as `proxima run --scene` reads a file; false with `error` in a local
  /// run's words about the client's files.
  bool buildScene(const net::SceneBundle& bundle, BuiltModel& model, std::string& error) const;

  ThreadedRuntime& m_runtime;
  ProxyParameters m_proxy;
  double m_stiffness;
  double m_rate;
  std::string m_token;
  ModelLimits m_limits;
  ModelOwnership m_ownership;
  /// One model is published at a time, so that versions go in commit order.
  std::mutex m_publishing;
  std::atomic<bool> m_stopping{false};
};

} // namespace proxima::detail
