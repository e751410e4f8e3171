// The live haptic server (Documentation/Server.md; paper section 7) on loopback: a threaded
// runtime reads a simulated finger that comes down and presses where the client's sphere will be;
// a client builds the sphere with GL-like calls and commits it while the loops run, and follows
// the proxy. Checked against geometry, not against the code under test: the proxy never comes
// inside the sphere (its distance from the centre against the polyhedron's inscribed radius),
// touch and untouch events come for the right shape, and an upload that dies or is malformed
// leaves the old model live while the state goes on.
#include "Geometry/ProceduralMeshes.h"
#include "IO/InputChecks/InputError.h"
#include "Net/HapticClient.h"
#include "Net/RemoteRuns.h"
#include "Runtime/SimulatedDevice.h"
#include "Runtime/ThreadedRuntime.h"

#include "proxima_haptic.grpc.pb.h"

#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <thread>

namespace proxima
{
namespace
{
using namespace std::chrono_literals;

constexpr double kSphereRadius = 0.05;
constexpr double kProxyRadius = 0.001;

// Above the sphere-to-be for 0.5 s, then down 5 mm into it by 1 s, held there.
FingerPath pressingFinger()
{
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 0.08});
  path.append(0.5, {0.0, 0.0, 0.08});
  path.append(1.0, {0.0, 0.0, 0.045});
  path.append(600.0, {0.0, 0.0, 0.045});
  return path;
}

// The nearest a point on the icosphere's surface comes to its centre: its faces' planes.
double inscribedRadius(const TriangleSoup& soup)
{
  double nearest = kSphereRadius;
  for (const auto& t : soup.triangles)
  {
    const Vec3& a = soup.points[t[0]];
    const Vec3 n = normalizedOrZero(cross(soup.points[t[1]] - a, soup.points[t[2]] - a));
    nearest = std::min(nearest, std::abs(dot(n, a)));
  }
  return nearest;
}

class LiveServer : public ::testing::Test
{
protected:
  LiveServer()
    : m_device(pressingFinger())
  {}

  void SetUp() override
  {
    RuntimeSettings settings;
    settings.servoRate = 1000.0;
    settings.realtimeScheduling = false;
    m_runtime = std::make_unique<ThreadedRuntime>(m_device, ServoParameters{}, settings);
    ProxyParameters proxy;
    proxy.radius = kProxyRadius;
    // Nothing to touch until a client uploads.
    m_runtime->publishScene(std::make_shared<CollisionScene>(), proxy, {0.0, 0.0, 0.08});
    std::string message;
    ASSERT_TRUE(m_runtime->start(message)) << message;
    startServer("127.0.0.1:0");
    m_address = "127.0.0.1:" + std::to_string(m_server->port());
  }

  // A server on `listen` in front of the fixture's runtime (as proxima serve --device makes one).
  void startServer(const std::string& listen)
  {
    RemoteServerSettings server;
    server.listen = listen;
    server.runtime = m_runtime.get();
    server.liveProxy.radius = kProxyRadius;
    m_server = std::make_unique<RemoteRunServer>(server);
  }

  void TearDown() override
  {
    m_server->shutdown();
    m_runtime->stop();
  }

  // Sphere `subdivisions` at `center` as a client shape.
  static void sphereShape(HapticClient& client, std::uint32_t subdivisions, const Vec3& center)
  {
    const TriangleSoup soup = makeIcosphere(subdivisions, kSphereRadius);
    client.pushMatrix();
    client.translate(center);
    client.beginShape("sphere");
    for (std::size_t i = 0; i < soup.points.size(); ++i)
    {
      client.normal(soup.pointNormals.empty() ? soup.points[i] : soup.pointNormals[i]);
      client.vertex(soup.points[i]);
    }
    for (const auto& t : soup.triangles)
    {
      client.triangle(t[0], t[1], t[2]);
    }
    client.endShape();
    client.popMatrix();
  }

  // A bare gRPC client of the server: no owner's key, no token, as any program speaking the
  // .proto directly.
  std::unique_ptr<net::HapticServer::Stub> bareStub() const
  {
    return net::HapticServer::NewStub(
      grpc::CreateChannel(m_address, grpc::InsecureChannelCredentials()));
  }

  SimulatedDevice m_device;
  std::unique_ptr<ThreadedRuntime> m_runtime;
  std::unique_ptr<RemoteRunServer> m_server;
  std::string m_address;
};

// What a client's stream gave, shared with its thread.
struct Collected
{
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<LiveSample> samples;
  std::vector<TouchChange> touches;

  template <typename Predicate>
  bool waitFor(Predicate predicate, std::chrono::seconds limit = 60s)
  {
    std::unique_lock<std::mutex> lock(mutex);
    return changed.wait_for(lock, limit, [&] { return predicate(*this); });
  }
};

void follow(HapticClient& client, Collected& collected, double rate)
{
  client.startStateStream(
    rate,
    [&collected](const LiveSample& sample) {
      const std::lock_guard<std::mutex> lock(collected.mutex);
      collected.samples.push_back(sample);
      collected.changed.notify_all();
    },
    [&collected](const TouchChange& touch) {
      const std::lock_guard<std::mutex> lock(collected.mutex);
      collected.touches.push_back(touch);
    });
}

TEST_F(LiveServer, AnUploadedShapeIsTouchedAndNeverEntered)
{
  HapticClient client(m_address);
  Collected collected;
  follow(client, collected, 200.0);
  sphereShape(client, 3, {});
  const ModelReceiptInfo receipt = client.commit();
  EXPECT_EQ(receipt.version, 2u); // the server's empty scene was 1
  EXPECT_EQ(receipt.shapes, 1u);
  EXPECT_EQ(receipt.triangles, 1280u);
  EXPECT_GE(receipt.liveMilliseconds, 0.0);
  // The receipt comes once the proxy loop has the model, not merely once it was handed over.
  EXPECT_GE(m_runtime->liveSceneVersion(), receipt.version);
  std::printf("[ measured ] 1,280 triangles: built in %.2f ms, live %.2f ms later\n",
              receipt.buildMilliseconds, receipt.liveMilliseconds);
  // The finger presses 5 mm into the sphere: wait for half a second of it held there.
  // Held: the finger at rest (after 1 s) and the model live for longer than the servo's
  // ramp after a swap (ServoParameters::sceneChangeWindow, 0.1 s).
  double live = -1.0;
  const auto isHeld = [&live, &receipt](const LiveSample& s) {
    if (s.modelVersion == receipt.version && live < 0.0)
    {
      live = s.time;
    }
    // Not fading: the runtime fades the force while its proxy loop is starved (a loaded machine).
    return live >= 0.0 && s.modelVersion == receipt.version && s.contacts > 0 &&
           s.time > std::max(1.05, live + 0.2) &&
           !TickConditions(s.flags).has(TickCondition::forceFading);
  };
  ASSERT_TRUE(collected.waitFor([&](const Collected& c) {
    live = -1.0;
    int held = 0;
    for (const LiveSample& s : c.samples)
    {
      held += isHeld(s) ? 1 : 0;
    }
    return held >= 100;
  }));
  live = -1.0;
  EXPECT_EQ(client.stopStateStream(), "");
  const double inscribed = inscribedRadius(makeIcosphere(3, kSphereRadius));
  double deepest = 0.0;
  int pressed = 0;
  for (const LiveSample& s : collected.samples)
  {
    const bool held = isHeld(s);
    if (s.modelVersion < receipt.version)
    {
      EXPECT_EQ(s.contacts, 0); // nothing to touch before
      continue;
    }
    deepest = std::max(deepest, inscribed + kProxyRadius - norm(s.proxy));
    if (s.contacts > 0)
    {
      ++pressed;
      EXPECT_EQ(s.shape, 0);
      // Out of the sphere. A sample the runtime flags as fading (its proxy loop starved for
      // longer than the watchdog's 5 ms) carries the last force scaled down to exactly 0 at the
      // fade's end, beside the stale proxy's contact: never into the sphere, but maybe 0.
      if (TickConditions(s.flags).has(TickCondition::forceFading))
      {
        EXPECT_GE(s.force.z, 0.0);
      }
      else
      {
        EXPECT_GT(s.force.z, 0.0);
      }
      if (held)
      {
        // Held 5 mm below the top: the spring kp (h + r - z_finger), with the surface's height h
        // above the finger between the inscribed radius and the sphere's.
        EXPECT_GE(s.force.z, 1000.0 * (inscribed + kProxyRadius - 0.045) - 1e-6);
        EXPECT_LE(s.force.z, 1000.0 * (kSphereRadius + kProxyRadius - 0.045) + 1e-6);
      }
    }
  }
  std::printf("[ measured ] %zu samples, %d pressing; deepest the proxy came inside: %.3g m\n",
              collected.samples.size(), pressed, deepest);
  EXPECT_LE(deepest, 1e-9);
  ASSERT_FALSE(collected.touches.empty());
  EXPECT_EQ(collected.touches.front().shape, 0);
  EXPECT_TRUE(collected.touches.front().touched);
}

TEST_F(LiveServer, ANewModelReplacesTheOldAndItsTouchEnds)
{
  HapticClient client(m_address);
  Collected collected;
  follow(client, collected, 500.0);
  sphereShape(client, 2, {});
  const std::uint64_t first = client.commit().version;
  ASSERT_TRUE(collected.waitFor([&](const Collected& c) {
    return !c.samples.empty() && c.samples.back().modelVersion == first &&
           c.samples.back().contacts > 0;
  }));
  // The same sphere 20 cm away: the finger touches nothing now.
  sphereShape(client, 2, {0.2, 0.0, 0.0});
  const ModelReceiptInfo second = client.commit();
  EXPECT_EQ(second.version, first + 1);
  ASSERT_TRUE(collected.waitFor([&](const Collected& c) {
    return c.samples.back().modelVersion == second.version && c.samples.back().contacts == 0 &&
           c.touches.size() >= 2;
  }));
  client.stopStateStream();
  EXPECT_TRUE(collected.touches[0].touched);
  EXPECT_EQ(collected.touches[1].shape, 0);
  EXPECT_FALSE(collected.touches[1].touched);
  // Ticks kept coming, in order, through both swaps.
  for (std::size_t i = 1; i < collected.samples.size(); ++i)
  {
    EXPECT_GE(collected.samples[i].tick, collected.samples[i - 1].tick);
  }
}

TEST_F(LiveServer, AnUploadThatDiesOrIsMalformedLeavesTheModelLive)
{
  std::uint64_t live = 0;
  {
    HapticClient owner(m_address);
    sphereShape(owner, 2, {});
    live = owner.commit().version;
  } // gone: no client owns the model, so a bare gRPC client may upload
  const std::uint64_t tickBefore = m_runtime->latestState().tick;

  // A client that dies in the middle of an upload: part of a 81,920-triangle sphere, then gone.
  {
    auto channel = grpc::CreateChannel(m_address, grpc::InsecureChannelCredentials());
    auto stub = net::HapticServer::NewStub(channel);
    grpc::ClientContext context;
    net::ModelReceipt receipt;
    auto writer = stub->UploadModel(&context, &receipt);
    const TriangleSoup big = makeIcosphere(6, kSphereRadius);
    net::ModelUpload upload;
    net::ShapePart& part = *upload.mutable_shape();
    for (std::size_t i = 0; i < 10000; ++i)
    {
      part.add_points(big.points[i].x);
      part.add_points(big.points[i].y);
      part.add_points(big.points[i].z);
    }
    ASSERT_TRUE(writer->Write(upload));
    context.TryCancel();
    EXPECT_FALSE(writer->Finish().ok());
  }
  HapticClient client(m_address);
  // A malformed model: a triangle beyond its points. Refused by name; nothing swapped.
  client.beginShape("broken");
  client.vertex({0.0, 0.0, 0.0});
  client.vertex({0.1, 0.0, 0.0});
  client.vertex({0.0, 0.1, 0.0});
  client.triangle(0, 1, 7);
  client.endShape();
  try
  {
    client.commit();
    ADD_FAILURE() << "a triangle index beyond the points was accepted";
  }
  catch (const std::invalid_argument& error)
  {
    std::printf("[ refused  ] %s\n", error.what());
    EXPECT_NE(std::string(error.what()).find("shape 0 ('broken')"), std::string::npos)
      << error.what();
  }
  EXPECT_EQ(m_runtime->liveSceneVersion(), live);
  // The haptic loops went on all along.
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (m_runtime->latestState().tick <= tickBefore && std::chrono::steady_clock::now() < deadline)
  {
    std::this_thread::sleep_for(1ms);
  }
  EXPECT_GT(m_runtime->latestState().tick, tickBefore);
  EXPECT_EQ(m_runtime->latestState().sceneVersion, live);
}

// The server restarts under an owner and an observer (same address, same device and runtime, as a
// restarted proxima serve): the observer's stream waits for the new server and goes on from it;
// the new server never granted the owner's key, and the owner's next commit is refused in words
// saying so (OwnershipEnded), not taken as if it still owned the model; the owner claims the
// model again on purpose, and then commits.
TEST_F(LiveServer, AnOwnerIsToldPlainlyThatARestartedServerEndedItsOwnership)
{
  HapticClient owner(m_address);
  sphereShape(owner, 2, {});
  const std::uint64_t live = owner.commit().version;
  EXPECT_TRUE(owner.ownsModel());
  HapticClient observer(ServerConnection{m_address, {}, {}}, HapticClientRole::Observer);
  Collected seen;
  follow(observer, seen, 200.0);
  ASSERT_TRUE(seen.waitFor([](const Collected& c) { return !c.samples.empty(); }));
  m_server.reset();
  startServer(m_address);
  sphereShape(owner, 2, Vec3{0.0, 0.0, -0.01});
  try
  {
    owner.commit();
    ADD_FAILURE() << "an owner's key from before the restart was taken";
  }
  catch (const OwnershipEnded& error)
  {
    std::printf("[ refused  ] %s\n", error.what());
    EXPECT_NE(std::string(error.what()).find("no longer owns the model"), std::string::npos)
      << error.what();
    EXPECT_NE(std::string(error.what()).find(m_address), std::string::npos) << error.what();
  }
  EXPECT_FALSE(owner.ownsModel());
  EXPECT_FALSE(owner.ownershipEnd().empty());
  EXPECT_EQ(owner.pendingShapes(), 1u);
  EXPECT_EQ(m_runtime->liveSceneVersion(), live);
  // The observer follows the new server: samples after the restart, the stream still running.
  ASSERT_TRUE(seen.waitFor(
    [](const Collected& c) { return !c.samples.empty() && c.samples.back().reconnections == 1; }))
    << observer.stateStreamEnd();
  EXPECT_EQ(observer.stateStreamEnd(), "");
  EXPECT_EQ(observer.stateStreamReconnections(), 1u);
  // Claimed again (the restarted server had no owner), the pending shape is committed.
  owner.claimOwnership();
  EXPECT_TRUE(owner.ownsModel());
  EXPECT_EQ(owner.ownershipEnd(), "");
  const std::uint64_t next = owner.commit().version;
  EXPECT_GT(next, live);
  ASSERT_TRUE(
    seen.waitFor([next](const Collected& c) { return c.samples.back().modelVersion == next; }));
  // Another client may not own it meanwhile: the owner holds it again.
  EXPECT_THROW(HapticClient second(m_address), InputError);
  EXPECT_EQ(observer.stopStateStream(), "");
}

// A server that goes away and does not come back within the policy's wait: the stream ends
// saying so, naming the address, and so does a commit; with no wait at all (maxWait 0) at once,
// as before clients reconnected.
TEST_F(LiveServer, AClientGivesUpOnAServerThatDoesNotComeBack)
{
  ServerConnection connection{m_address, {}, {}};
  connection.reconnect.maxWait = 300ms;
  HapticClient owner(connection);
  HapticClient observer(connection, HapticClientRole::Observer);
  Collected seen;
  follow(observer, seen, 200.0);
  ASSERT_TRUE(seen.waitFor([](const Collected& c) { return !c.samples.empty(); }));
  m_server->shutdown();
  const std::string ended = observer.waitForEnd(std::chrono::steady_clock::now() + 60s);
  EXPECT_EQ(observer.stopStateStream(), ended);
  std::printf("[ gave up  ] %s\n", ended.c_str());
  EXPECT_NE(ended.find("did not come back within 0.3 s"), std::string::npos) << ended;
  EXPECT_NE(ended.find(m_address), std::string::npos) << ended;
  sphereShape(owner, 1, {});
  try
  {
    owner.commit();
    ADD_FAILURE() << "a commit to a server that has gone went through";
  }
  catch (const InputError& error)
  {
    std::printf("[ gave up  ] %s\n", error.what());
    EXPECT_EQ(error.path(), "--server");
    EXPECT_NE(std::string(error.what()).find(m_address), std::string::npos) << error.what();
  }
}

TEST_F(LiveServer, AClientThatStopsReadingLosesSamplesNotTheServersTime)
{
  // A small receive window, not grown by bandwidth probing: the server's writes to a reader that
  // stops block within a few hundred samples, whatever the machine's socket buffers (with the
  // defaults, a loopback connection absorbs many seconds of samples before they do).
  grpc::ChannelArguments arguments;
  arguments.SetInt(GRPC_ARG_HTTP2_BDP_PROBE, 0);
  arguments.SetInt(GRPC_ARG_HTTP2_STREAM_LOOKAHEAD_BYTES, 16384);
  auto channel =
    grpc::CreateCustomChannel(m_address, grpc::InsecureChannelCredentials(), arguments);
  auto stub = net::HapticServer::NewStub(channel);
  grpc::ClientContext context;
  net::StateRequest request;
  request.set_rate_hz(1000.0);
  auto reader = stub->StreamState(&context, request);
  net::StateSample first;
  ASSERT_TRUE(reader->Read(&first));
  // Three seconds without reading: gRPC's flow control fills, the server's writes block.
  std::this_thread::sleep_for(3s);
  net::StateSample sample;
  std::uint64_t dropped = 0;
  std::uint64_t newest = first.tick();
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (dropped == 0 && std::chrono::steady_clock::now() < deadline && reader->Read(&sample))
  {
    dropped = sample.dropped_samples();
    newest = sample.tick();
  }
  context.TryCancel();
  reader->Finish();
  std::printf("[ measured ] a reader 3 s late at 1 kHz: %llu samples dropped, samples from tick "
              "%llu to %llu\n",
              static_cast<unsigned long long>(dropped),
              static_cast<unsigned long long>(first.tick()),
              static_cast<unsigned long long>(newest));
  EXPECT_GT(dropped, 0u);
  // The haptic loops did not wait: the ticks went on at the servo's rate meanwhile (1 kHz: at
  // least two thousand in three seconds, however slow the machine's scheduling).
  EXPECT_GT(m_runtime->latestState().tick, first.tick() + 2000);
}

TEST_F(LiveServer, BadRequestsAreRefusedInWords)
{
  HapticClient client(m_address);
  client.startStateStream(5000.0, {});
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (client.stateStreamEnd().empty() && std::chrono::steady_clock::now() < deadline)
  {
    std::this_thread::sleep_for(1ms);
  }
  const std::string end = client.stopStateStream();
  EXPECT_NE(end.find("rate_hz: must be from 1 to 1000"), std::string::npos) << end;
  EXPECT_THROW(client.popMatrix(), std::logic_error);
  EXPECT_THROW(client.vertex({0.0, 0.0, 0.0}), std::logic_error);
  EXPECT_THROW(HapticClient("127.0.0.1:1"), std::exception);
}

} // namespace
} // namespace proxima

namespace proxima
{

TEST_F(LiveServer, OneClientOwnsTheModelAndTheOthersObserve)
{
  auto owner = std::make_unique<HapticClient>(m_address);
  EXPECT_EQ(owner->role(), HapticClientRole::Owner);
  // A second owner is refused in words; an observer follows but may not commit.
  try
  {
    HapticClient second(m_address);
    ADD_FAILURE() << "two clients owned the model";
  }
  catch (const InputError& error)
  {
    std::printf("[ refused  ] %s\n", error.what());
    EXPECT_NE(std::string(error.what()).find("another client owns the model"), std::string::npos)
      << error.what();
  }
  HapticClient observer(ServerConnection{m_address, {}, {}}, HapticClientRole::Observer);
  sphereShape(observer, 1, {});
  EXPECT_THROW(observer.commit(), std::logic_error);
  // A bare gRPC upload without the owner's key is refused by the server itself.
  {
    auto stub = bareStub();
    grpc::ClientContext context;
    net::ModelReceipt receipt;
    auto writer = stub->UploadModel(&context, &receipt);
    net::ModelUpload commit;
    commit.set_commit(true);
    writer->Write(commit);
    writer->WritesDone();
    const grpc::Status status = writer->Finish();
    EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
    EXPECT_NE(status.error_message().find("only it may change it"), std::string::npos);
  }
  Collected seen;
  follow(observer, seen, 200.0);
  sphereShape(*owner, 2, {});
  const std::uint64_t version = owner->commit().version;
  ASSERT_TRUE(seen.waitFor([&](const Collected& c) {
    return !c.samples.empty() && c.samples.back().modelVersion == version;
  }));
  // The owner goes: another client may own the model as soon as it has (the server lets go
  // before the owner's call ends), and change it.
  owner.reset();
  auto next = std::make_unique<HapticClient>(m_address);
  sphereShape(*next, 1, {0.2, 0.0, 0.0});
  const std::uint64_t nextVersion = next->commit().version;
  EXPECT_EQ(nextVersion, version + 1);
  ASSERT_TRUE(
    seen.waitFor([&](const Collected& c) { return c.samples.back().modelVersion == nextVersion; }));
  EXPECT_EQ(observer.stopStateStream(), "");
}

// A scene file as the model, sent with its mesh: a plate (box.obj, 10 x 20 x 1 cm) on a slide
// joint along z with a spring of ks = 1000 N/m, its top at z = 5 cm under the finger that presses
// to 4.5 cm. Two springs in series, kp and ks: at rest the plate is pushed down by
// d = kp (h + r - z_finger) / (kp + ks) and the force is ks d (no geometry of the code's own).
TEST_F(LiveServer, ASceneFileIsUploadedWithItsFilesAndItsBodiesMove)
{
  std::string folder = ::testing::TempDir();
  if (!folder.empty() && folder.back() == '/')
  {
    folder.pop_back();
  }
  const std::string scene = folder + "/spring-plate.json";
  {
    std::ofstream out(scene);
    out << R"({"version": 2, "objects": [{"mesh": ")" << PROXIMA_SOURCE_DATA
        << R"(/Meshes/box.obj", "pose": {"translation": [0, 0, 0.045]},
         "material": {"static_friction": 0.2, "dynamic_friction": 0.1},
         "body": {"joint": {"type": "slide", "axis": [0, 0, 1], "anchor": [0, 0, 0.045],
                            "stiffness": 1000, "damping": 20},
                  "density": 1000}}]})";
  }
  HapticClient client(m_address);
  Collected collected;
  follow(client, collected, 200.0);
  client.scene(scene);
  EXPECT_THROW(client.vertex({0.0, 0.0, 0.0}), std::logic_error);
  const ModelReceiptInfo receipt = client.commit();
  EXPECT_EQ(receipt.shapes, 1u);
  EXPECT_EQ(receipt.triangles, 12u);
  const double kp = 1000.0;
  const double ks = 1000.0;
  const double d = kp * (0.05 + kProxyRadius - 0.045) / (kp + ks);
  // Held: the finger at rest for over a second, the plate settled (damping ratio 0.7).
  ASSERT_TRUE(collected.waitFor([&](const Collected& c) {
    int held = 0;
    for (const LiveSample& s : c.samples)
    {
      held += (s.modelVersion == receipt.version && s.time > 2.5 &&
               !TickConditions(s.flags).has(TickCondition::forceFading))
                ? 1
                : 0;
    }
    return held >= 50;
  }));
  client.stopStateStream();
  int checked = 0;
  for (const LiveSample& s : collected.samples)
  {
    if (s.modelVersion == receipt.version && s.time > 2.5 &&
        !TickConditions(s.flags).has(TickCondition::forceFading))
    {
      ++checked;
      EXPECT_EQ(s.shape, 0);
      EXPECT_NEAR(s.proxy.z, 0.05 + kProxyRadius - d, 2e-5);
      EXPECT_NEAR(s.force.z, ks * d, 0.02);
      // The plate's pose, streamed: down its slide by d.
      ASSERT_EQ(s.bodies.size(), 1u);
      EXPECT_EQ(s.bodies[0].shape, 0);
      EXPECT_NEAR(s.bodies[0].pose.translation.z, -d, 2e-5);
      EXPECT_NEAR(s.bodies[0].pose.translation.x, 0.0, 1e-12);
    }
  }
  const LiveSample& last = collected.samples.back();
  std::printf("[ measured ] the plate pushed down: proxy z %.6f m (closed form %.6f), force "
              "%.4f N (closed form %.4f), %d samples\n",
              last.proxy.z, 0.05 + kProxyRadius - d, last.force.z, ks * d, checked);

  // A scene whose mesh is broken is refused in the words of a local run, naming the client's
  // files; the plate stays.
  const std::string broken = folder + "/broken-scene.json";
  const std::string brokenMesh = folder + "/broken.obj";
  {
    std::ofstream(brokenMesh) << "v 0 0 0\nv 1 0 0\nf 1 2 3\n";
    std::ofstream(broken) << R"({"version": 1, "objects": [{"mesh": "broken.obj"}]})";
  }
  client.scene(broken);
  try
  {
    client.commit();
    ADD_FAILURE() << "a broken mesh in a scene was accepted";
  }
  catch (const std::invalid_argument& error)
  {
    std::printf("[ refused  ] %s\n", error.what());
    EXPECT_NE(std::string(error.what()).find(brokenMesh), std::string::npos) << error.what();
  }
  EXPECT_EQ(m_runtime->liveSceneVersion(), receipt.version);
}

// A bundle whose scene names a file of the server's own, or an MJCF file that names files, sent by
// a bare gRPC client (no client owns the model): refused, nothing read there, the model kept.
TEST_F(LiveServer, ABundledSceneNamesOnlyItsOwnFiles)
{
  // The server's empty scene, once the proxy loop has it (at its first tick).
  ASSERT_TRUE(m_runtime->waitForScene(1, 30s));
  const std::uint64_t live = m_runtime->liveSceneVersion();
  ASSERT_EQ(live, 1u);
  const auto bareUpload = [this](const std::string& json, const std::string& mjcf) {
    auto stub = bareStub();
    grpc::ClientContext context;
    net::ModelReceipt receipt;
    auto writer = stub->UploadModel(&context, &receipt);
    net::ModelUpload upload;
    net::SceneBundle& bundle = *upload.mutable_scene();
    bundle.set_scene_name("client.json");
    bundle.set_scene_json(json);
    net::BundledFile* mesh = bundle.add_files();
    mesh->set_local_name("file0.obj");
    mesh->set_client_name("plate.obj");
    mesh->set_data("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    if (!mjcf.empty())
    {
      net::BundledFile* mechanism = bundle.add_files();
      mechanism->set_local_name("file1.xml");
      mechanism->set_client_name("mechanism.xml");
      mechanism->set_data(mjcf);
    }
    writer->Write(upload);
    net::ModelUpload commit;
    commit.set_commit(true);
    writer->Write(commit);
    writer->WritesDone();
    return writer->Finish();
  };
  const grpc::Status elsewhere =
    bareUpload(R"({"version": 1, "objects": [{"mesh": "/etc/hostname"}]})", {});
  EXPECT_EQ(elsewhere.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(elsewhere.error_message().find("not a file of the upload"), std::string::npos)
    << elsewhere.error_message();
  const grpc::Status includes = bareUpload(
    R"({"version": 2, "mjcf": "file1.xml", "objects": [{"mesh": "file0.obj", "body": {"name": "b"}}]})",
    R"(<mujoco><include file="/etc/other.xml"/><worldbody><body name="b"><joint type="hinge"/>)"
    R"(<geom size="0.1"/></body></worldbody></mujoco>)");
  EXPECT_EQ(includes.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(includes.error_message().find("names files of its own"), std::string::npos)
    << includes.error_message();
  EXPECT_EQ(m_runtime->liveSceneVersion(), live);
}

} // namespace proxima
