#include "Net/Private/LiveHapticService.h"

#include "IO/Scene/SceneBuilder.h"
#include "IO/Scene/SceneFile.h"
#include "IO/ScriptedRun/ScriptedRun.h"
#include "Net/Private/RunFolder.h"
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
  switch (m_ownership.mayChange(*context))
  {
    case ModelOwnership::Right::Granted: break;
    case ModelOwnership::Right::OwnedByAnother:
      return {grpc::StatusCode::FAILED_PRECONDITION,
              "another client owns the model: only it may change it (this client may observe)"};
    case ModelOwnership::Right::OwnershipEnded:
      return {grpc::StatusCode::FAILED_PRECONDITION,
              "this client no longer owns the model: its ownership ended when its connection to "
              "the server dropped or the server restarted; the model is unchanged (claim the "
              "ownership again to change it)"};
  }
  ModelAssembly shapes(m_limits);
  net::SceneBundle sceneBundle;
  bool hasScene = false;
  net::ModelUpload upload;
  bool committed = false;
  std::string error;
  const char* const mixed = "an upload is shapes or one scene file, not both (nor two scenes)";
  while (!committed && reader->Read(&upload))
  {
    if (upload.has_shape())
    {
      if (hasScene)
      {
        return {grpc::StatusCode::INVALID_ARGUMENT, mixed};
      }
      if (!shapes.add(upload.shape(), error))
      {
        return {grpc::StatusCode::INVALID_ARGUMENT, error};
      }
    }
    else if (upload.has_scene())
    {
      if (hasScene || shapes.numShapes() > 0)
      {
        return {grpc::StatusCode::INVALID_ARGUMENT, mixed};
      }
      sceneBundle = std::move(*upload.mutable_scene());
      hasScene = true;
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
  BuiltModel model;
  if (hasScene)
  {
    if (!buildScene(sceneBundle, model, error))
    {
      return {grpc::StatusCode::INVALID_ARGUMENT, error};
    }
  }
  else
  {
    model.scene = std::make_shared<CollisionScene>();
    if (!shapes.build(*model.scene, error))
    {
      return {grpc::StatusCode::INVALID_ARGUMENT, error};
    }
    model.shapes = static_cast<std::uint32_t>(shapes.numShapes());
    model.triangles = shapes.numTriangles();
  }
  const double buildMilliseconds = millisecondsSince(buildStart);
  const auto publishStart = Clock::now();
  std::uint64_t version = 0;
  {
    // The runtime keeps the proxy where its loop left it only once a scene is live; before the
    // loop's first tick (a commit right after the server started) the start given here would
    // count, and the latest state's proxy is not yet known. The server published its empty
    // scene with the device's start before it began to serve: wait until the loop has it.
    m_runtime.waitForScene(1, std::chrono::seconds(5));
    const std::lock_guard<std::mutex> lock(m_publishing);
    version = m_runtime.publishScene(std::move(model.scene), m_proxy, m_runtime.latestState().proxy,
                                     nullptr, std::move(model.dynamics));
  }
  // Live once the proxy loop has installed it (it does at its next tick, unless the runtime has
  // stopped; -1 then).
  const bool live = m_runtime.waitForScene(version, std::chrono::seconds(5));
  receipt->set_version(version);
  receipt->set_shapes(model.shapes);
  receipt->set_triangles(model.triangles);
  receipt->set_build_ms(buildMilliseconds);
  receipt->set_live_ms(live ? millisecondsSince(publishStart) : -1.0);
  return grpc::Status::OK;
}

bool LiveHapticService::buildScene(const net::SceneBundle& bundle, BuiltModel& model,
                                   std::string& error) const
{
  try
  {
    RunFolder folder;
    try
    {
      const SceneDescription description = readSceneFile(folder.writeScene(bundle));
      folder.requireBundledFiles(description);
      LoadedScene loaded = proxima::buildScene(description);
      for (const LoadedObject& object : loaded.objects)
      {
        model.triangles += object.numTriangles;
      }
      if (model.triangles > m_limits.maxTriangles)
      {
        error = bundle.scene_name() + ": the scene has " + std::to_string(model.triangles) +
                " triangles, more than this server takes in one model (" +
                std::to_string(m_limits.maxTriangles) + ")";
        return false;
      }
      ScriptedRunSettings coupling;
      coupling.stiffness = m_stiffness;
      coupling.rate = m_rate;
      model.dynamics = sceneDynamics(coupling, loaded);
      model.shapes = static_cast<std::uint32_t>(loaded.objects.size());
      model.scene = std::shared_ptr<CollisionScene>(std::move(loaded.scene));
      return true;
    }
    catch (const std::exception& refused)
    {
      // A local run's words (InputError: "<file>: <defect>"), about the client's files.
      error = folder.clientWords(refused.what());
      return false;
    }
  }
  catch (const std::exception& failed)
  {
    error = failed.what();
    return false;
  }
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
    sample.set_flags(state.conditions.bits());
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
    const BodyPoses bodies = m_runtime.latestBodyPoses();
    for (int b = 0; b < bodies.count; ++b)
    {
      net::BodyPose* pose = sample.add_bodies();
      pose->set_shape(static_cast<std::int32_t>(bodies.objects[b]));
      setVector(bodies.poses[b].row[0], pose->mutable_row_x());
      setVector(bodies.poses[b].row[1], pose->mutable_row_y());
      setVector(bodies.poses[b].row[2], pose->mutable_row_z());
      setVector(bodies.poses[b].translation, pose->mutable_translation());
    }
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
  if (m_stopping)
  {
    // The server is going away (it may come back: a restart); a client waits for it on this code.
    return {grpc::StatusCode::UNAVAILABLE, "the server stopped"};
  }
  return grpc::Status::OK;
}

grpc::Status LiveHapticService::HoldOwnership(
  grpc::ServerContext* context,
  grpc::ServerReaderWriter<net::OwnershipGrant, net::OwnershipRequest>* stream)
{
  if (!tokenAccepted(*context, m_token))
  {
    return {grpc::StatusCode::UNAUTHENTICATED, "the server refused the token (missing or wrong)"};
  }
  std::string holder;
  const std::string key = m_ownership.claim(context->peer(), holder);
  if (key.empty())
  {
    return {grpc::StatusCode::FAILED_PRECONDITION,
            "another client owns the model (" + holder +
              "): connect as an observer, or once it has gone"};
  }
  net::OwnershipGrant grant;
  grant.set_key(key);
  if (stream->Write(grant))
  {
    // Held until the client ends its side (Read returns false), or goes away (its connection
    // drops), or the server shuts down (which cancels the call).
    net::OwnershipRequest ignored;
    while (stream->Read(&ignored))
    {}
  }
  // Let go before the call ends, so that a client whose call has ended knows it no longer owns.
  m_ownership.release(key);
  return grpc::Status::OK;
}

} // namespace proxima::detail
