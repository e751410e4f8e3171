#include "Net/Private/LiveHapticService.h"

#include "Net/Private/TokenCheck.h"

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

namespace proxima::detail
{

namespace
{
using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void setVector(const Vec3& v, net::Vector3* out)
{
  out->set_x(v.x);
  out->set_y(v.y);
  out->set_z(v.z);
}

// The shapes a tick touches, as a bit set (the first 64; a model's later shapes share the last
// bit, which is only for events).
std::uint64_t touchedShapes(const HapticState& state)
{
  std::uint64_t touched = 0;
  for (int i = 0; i < state.numContacts; ++i)
  {
    touched |= std::uint64_t{1} << std::min<std::uint32_t>(state.contacts[i].object, 63);
  }
  return touched;
}
} // namespace

grpc::Status LiveHapticService::UploadModel(grpc::ServerContext* context,
                                            grpc::ServerReader<net::ModelUpload>* reader,
                                            net::ModelReceipt* receipt)
{
  if (!tokenAccepted(*context, m_token))
  {
    return {grpc::StatusCode::UNAUTHENTICATED, "the server refused the token (missing or wrong)"};
  }
  ModelAssembly model(m_limits);
  net::ModelUpload upload;
  bool committed = false;
  std::string error;
  while (!committed && reader->Read(&upload))
  {
    if (upload.has_shape())
    {
      if (!model.add(upload.shape(), error))
      {
        return {grpc::StatusCode::INVALID_ARGUMENT, error};
      }
    }
    else if (upload.commit())
    {
      committed = true;
    }
  }
  if (!committed)
  {
    // The client went away, or ended without committing: the old model stays.
    return {grpc::StatusCode::ABORTED, "the upload ended without a commit; the model is unchanged"};
  }
  const auto buildStart = Clock::now();
  auto scene = std::make_shared<CollisionScene>();
  if (!model.build(*scene, error))
  {
    return {grpc::StatusCode::INVALID_ARGUMENT, error};
  }
  const double buildMilliseconds = millisecondsSince(buildStart);
  const auto publishStart = Clock::now();
  std::uint64_t version = 0;
  {
    const std::lock_guard<std::mutex> lock(m_publishing);
    version = m_runtime.publishScene(std::move(scene), m_proxy, m_runtime.latestState().proxy);
  }
  // Live once the proxy loop has installed it (it does at its next tick, unless the runtime has
  // stopped).
  const auto deadline = publishStart + std::chrono::seconds(5);
  while (m_runtime.liveSceneVersion() < version && Clock::now() < deadline && !m_stopping)
  {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  receipt->set_version(version);
  receipt->set_shapes(static_cast<std::uint32_t>(model.numShapes()));
  receipt->set_triangles(model.numTriangles());
  receipt->set_build_ms(buildMilliseconds);
  receipt->set_live_ms(m_runtime.liveSceneVersion() >= version ? millisecondsSince(publishStart)
                                                               : -1.0);
  return grpc::Status::OK;
}

grpc::Status LiveHapticService::StreamState(grpc::ServerContext* context,
                                            const net::StateRequest* request,
                                            grpc::ServerWriter<net::StateSample>* writer)
{
  if (!tokenAccepted(*context, m_token))
  {
    return {grpc::StatusCode::UNAUTHENTICATED, "the server refused the token (missing or wrong)"};
  }
  const double rate = request->rate_hz();
  if (!std::isfinite(rate) || rate < 1.0 || rate > 1000.0)
  {
    return {grpc::StatusCode::INVALID_ARGUMENT,
            "rate_hz: must be from 1 to 1000 samples per second"};
  }
  const auto period =
    std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate));
  std::uint64_t touched = 0;
  std::uint64_t dropped = 0;
  auto next = Clock::now();
  while (!context->IsCancelled() && !m_stopping)
  {
    const HapticState state = m_runtime.latestState();
    net::StateSample sample;
    sample.set_tick(state.tick);
    sample.set_t(state.time);
    setVector(state.finger, sample.mutable_finger());
    setVector(state.proxy, sample.mutable_proxy());
    setVector(state.force, sample.mutable_force());
    sample.set_contacts(state.numContacts);
    sample.set_shape(state.contactObject);
    sample.set_flags(tickFlags(state));
    sample.set_model_version(state.sceneVersion);
    const std::uint64_t now = touchedShapes(state);
    for (int shape = 0; shape < 64; ++shape)
    {
      const std::uint64_t bit = std::uint64_t{1} << shape;
      if ((now & bit) != (touched & bit))
      {
        net::TouchEvent* event = sample.add_events();
        event->set_shape(shape);
        event->set_touched((now & bit) != 0);
      }
    }
    touched = now;
    sample.set_dropped_samples(dropped);
    sample.set_sent_ns(std::chrono::duration_cast<std::chrono::nanoseconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count());
    if (!writer->Write(sample))
    {
      break; // the client went away
    }
    // The next sample on the stream's own clock. A write that blocked (a client reading too
    // slowly: gRPC's flow control) costs the samples whose times it overran, counted; the haptic
    // threads never wait for it.
    next += period;
    const auto after = Clock::now();
    if (after > next + period)
    {
      const auto late = after - next;
      const auto missed = static_cast<std::uint64_t>(late / period);
      dropped += missed;
      next += period * static_cast<long>(missed);
    }
    std::this_thread::sleep_until(next);
  }
  return grpc::Status::OK;
}

} // namespace proxima::detail
