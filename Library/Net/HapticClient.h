// The application's side of the live haptic server (paper section 7's "HL", a GL-like network
// library; Documentation/Server.md): shapes made of vertices and triangles under a stack of
// transforms, with materials, or read from mesh files, sent to `proxima serve --device` as a
// model that is swapped in only when it is committed and built there; and the proxy, finger,
// force and touch events streamed back at the rate asked for. gRPC stays in HapticClient.cpp.
//
//   HapticClient client("127.0.0.1:50051");
//   client.translate({0.0, 0.0, -0.05});
//   client.beginShape("floor");
//   client.vertex({-1, -1, 0}); client.vertex({1, -1, 0}); client.vertex({0, 1, 0});
//   client.triangle(0, 1, 2);
//   client.endShape();
//   client.commit();                       // live on the server when this returns
//   client.startStateStream(100.0, [](const LiveSample& s) { draw(s.proxy); },
//                           [](const TouchChange& t) { if (t.touched) beep(); });
#pragma once

#include "Core/RigidTransform.h"
#include "Core/Vec3.h"
#include "IO/InputChecks/InputError.h"
#include "Net/ServerConnection.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace proxima
{

/// What a shape's surface feels like: the factor on the servo's stiffness, friction and
/// viscosity (N s/m), as a scene file's material.
struct ShapeMaterialSpec
{
  /// Factor on the servo's stiffness kp: 0 to 100, 0 taken as 1 (the server refuses others).
  double stiffness = 1.0;
  /// Static friction coefficient mu_s, 0 (none) to 10.
  double staticFriction = 0.0;
  /// Dynamic friction coefficient mu_d, felt while sliding, 0 (none) to 10.
  double dynamicFriction = 0.0;
  /// Viscosity in N s/m, 0 (none) to 1e4.
  double viscosity = 0.0;
};

/// The server's answer to a commit.
struct ModelReceiptInfo
{
  /// The model's scene version in the server's runtime (samples carry it).
  std::uint64_t version = 0;
  /// Shapes in the model (a scene file's objects).
  std::uint32_t shapes = 0;
  /// Triangles in the model, over all its shapes.
  std::uint64_t triangles = 0;
  /// Wall time the server took to build the model's sphere trees (ms).
  double buildMilliseconds = 0.0;
  /// Wall time from the build's end until the proxy loop used the model (ms); -1 if it did not
  /// within 5 s, e.g. a runtime that has stopped.
  double liveMilliseconds = 0.0;
};

/// Where a moving shape (a body of an uploaded scene) is: a point p of the shape as committed is
/// now at pose.apply(p).
struct LiveBodyPose
{
  /// The shape's index in the model (its object in the scene file).
  int shape = 0;
  /// The shape's rigid motion from where it was committed, in the model's frame (m).
  RigidTransform pose;
};

/// One sample of the server's state.
struct LiveSample
{
  /// The servo tick that produced the state (a restarted server counts its ticks anew).
  std::uint64_t tick = 0;
  /// The tick's time on the server runtime's clock (s).
  double time = 0.0;
  /// Where the device put the finger at that tick, in the model's frame (m).
  Vec3 finger;
  /// The proxy's centre, in the model's frame (m).
  Vec3 proxy;
  /// The force commanded to the device, on the finger (N), after clamping, rate limiting and
  /// fading.
  Vec3 force;
  /// Active constraint planes, 0 (free) to 3.
  int contacts = 0;
  /// The shape of the first contact, -1 for none.
  int shape = -1;
  /// The tick's conditions as `TickConditions::bits()` (Core/TickConditions.h): the trace's
  /// flags column.
  std::uint32_t flags = 0;
  /// The version of the model the tick's proxy step ran on (ModelReceiptInfo::version).
  std::uint64_t modelVersion = 0;
  /// Samples the server could not send on time because this client read too slowly, so far.
  std::uint64_t droppedSamples = 0;
  /// The model's bodies (a scene with bodies) after the server's newest dynamics step.
  std::vector<LiveBodyPose> bodies;
  /// The server's wall clock when it wrote the sample (ns since 1970).
  std::int64_t sentNanoseconds = 0;
  /// This client's wall clock when it read the sample (ns since 1970): less sentNanoseconds, the
  /// stream's latency where the clocks agree (one machine, or synchronised ones).
  std::int64_t receivedNanoseconds = 0;
  /// How many times the stream has come back after its server went away (a restarted server
  /// starts its ticks and model versions anew).
  std::uint32_t reconnections = 0;
};

/// A shape's touch began or ended (seen between two samples).
struct TouchChange
{
  /// The shape's index in the model; shapes from 63 on are all reported as 63.
  int shape = 0;
  /// True when the touch began, false when it ended.
  bool touched = false;
  /// The time of the sample that saw the change (LiveSample::time, s).
  double time = 0.0;
};

/// One client at a time owns the server's model and may change it; any number observe it
/// (follow its state).
enum class HapticClientRole
{
  Owner,
  Observer
};

/// An owner learns that it no longer owns the model: its ownership ended with its connection
/// (the server went away or restarted, and a restarted server has lost the model). An InputError
/// naming --server; HapticClient::claimOwnership claims the model again.
class OwnershipEnded : public InputError
{
public:
  /// An error about `path` (--server) with `defect` in words, as InputError's.
  using InputError::InputError;
};

/// A server that goes away and comes back on the same address (a restart) is waited for, by the
/// connection's ReconnectPolicy: a call that fails because the server is unavailable is made again
/// once it answers, the state stream goes on (LiveSample::reconnections counts), and only after
/// the policy's maxWait is it an InputError naming --server and the address. The owner is the
/// exception: its ownership ends with the connection it was granted on, and it is told so
/// (OwnershipEnded) rather than claiming the model again behind the application's back, which
/// would have it believe its model still there; claimOwnership() claims it again on purpose.
class HapticClient
{
public:
  /// Connects to `server` (HOST:PORT) as the owner. Throws InputError naming --server when
  /// nothing answers, or when another client owns the model (no waiting: the first connection is
  /// not retried).
  explicit HapticClient(const std::string& server, const std::string& token = {});
  /// Connects as `role`, with the connection's token and TLS roots. An owner holds the model
  /// until it is destroyed (or its process ends, or its connection drops); then another client
  /// may own it. Throws as above.
  explicit HapticClient(const ServerConnection& connection,
                        HapticClientRole role = HapticClientRole::Owner);
  ~HapticClient();
  HapticClient(const HapticClient&) = delete;
  HapticClient& operator=(const HapticClient&) = delete;

  /// Sets the top of the transform stack to the identity. The stack holds rigid motions; its top
  /// applies to the vertices, normals and mesh files given after (not to a scene file).
  void loadIdentity();
  /// Pushes a copy of the top of the stack, for popMatrix to return to.
  void pushMatrix();
  /// Throws std::logic_error on an empty stack.
  void popMatrix();
  /// Composes `transform` into the top of the stack, applied to a point before the top as it
  /// was (as OpenGL's glMultMatrix).
  void multMatrix(const RigidTransform& transform);
  /// Composes a translation by `offset` (m) into the top of the stack, as multMatrix does.
  void translate(const Vec3& offset);
  /// Right-handed about `axis` (any length but zero).
  void rotate(double degrees, const Vec3& axis);

  /// The material of the shapes begun after.
  void material(const ShapeMaterialSpec& material);
  /// A shape: its vertices (indices 0, 1, ... in order), the normal and texture coordinate that
  /// go with each vertex given after them (all or none of a shape's vertices have them), and its
  /// triangles by vertex index. Throws std::logic_error when the calls are out of order.
  void beginShape(const std::string& name = {});
  /// The normal, turned by the top of the stack, of the vertices given after it in this shape
  /// (until the next normal); a shape with normals is force-shaded.
  void normal(const Vec3& normal);
  /// The texture coordinate (u, v) of the vertices given after it in this shape (until the next
  /// texCoord).
  void texCoord(double u, double v);
  /// A vertex at `position` (m), moved by the top of the stack; its index is the number of
  /// vertices the shape had before it.
  void vertex(const Vec3& position);
  /// A triangle by the indices of three of the shape's vertices (the server checks them at
  /// commit).
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  /// Ends the shape beginShape began.
  void endShape();
  /// A shape read from a mesh file here (IO/Mesh/MeshReader.h: its errors), scaled, then
  /// transformed, with the current material.
  void mesh(const std::string& file, double scale = 1.0, const std::string& name = {});
  /// A scene file as the whole model (Documentation/SceneFiles.md: its objects, poses,
  /// materials, textures and bodies), checked and read here with every file it names, and read
  /// there as `proxima run --scene` reads it; the transform stack does not apply. Throws
  /// InputError as a local run would, std::logic_error when shapes are pending (and shape calls
  /// throw while a scene is).
  void scene(const std::string& file);
  /// The shapes the next commit sends: those made since the last commit, with one begun and not
  /// yet ended (a pending scene file is not counted).
  std::size_t pendingShapes() const;
  /// The role this client connected as; an owner keeps it after its ownership ends.
  HapticClientRole role() const;

  /// True while this owner's ownership holds: false for an observer, and once the connection it
  /// was granted on has dropped (the server went away or restarted). Any thread.
  bool ownsModel() const;
  /// Why an owner's ownership ended without its asking (OwnershipEnded's words), empty while it
  /// holds. Any thread.
  std::string ownershipEnd() const;
  /// Claims the model again for an owner whose ownership ended, waiting for a server that went
  /// away to answer (ReconnectPolicy); nothing while it still owns. Throws InputError naming
  /// --server when another client owns the model now or the server does not come back,
  /// std::logic_error for an observer. The model of a server that restarted is empty: commit it
  /// again.
  void claimOwnership();

  /// Sends the shapes made since the last commit as the server's new model and returns once the
  /// server has it live; they are then forgotten here. A server that goes away meanwhile is waited
  /// for (ReconnectPolicy). Throws std::invalid_argument with the server's words for a model it
  /// refuses (the old model stays), OwnershipEnded once this owner's ownership has ended (the
  /// shapes stay pending), InputError naming --server or --token-file, std::logic_error for an
  /// observer, std::runtime_error otherwise.
  ModelReceiptInfo commit();

  /// Streams the server's state at `rateHz` (1 to 1000) on a thread of this client's, handing
  /// each sample and each touch change to the callbacks there, until stopStateStream (or the
  /// client's end). One stream at a time. A server that goes away is waited for and the stream
  /// goes on from it when it answers again (ReconnectPolicy); after the policy's maxWait the
  /// stream ends (stateStreamEnd says so).
  void startStateStream(double rateHz, std::function<void(const LiveSample&)> onSample,
                        std::function<void(const TouchChange&)> onTouch = {});
  /// Why the stream ended by itself (the server went away, refused the rate...), empty while it
  /// runs or after stopStateStream asked it to end. Any thread.
  std::string stateStreamEnd() const;
  /// Waits until the stream ends by itself, or this owner's ownership ends, or `deadline` passes;
  /// returns why it ended (stateStreamEnd(), else ownershipEnd()), empty at the deadline.
  std::string waitForEnd(std::chrono::steady_clock::time_point deadline);
  /// Makes waitForEnd return now and from then on, as at its deadline (any thread: a thread that
  /// waits for a stop signal, say).
  void interruptWait();
  /// How many times the stream has come back after its server went away. Any thread.
  std::uint32_t stateStreamReconnections() const;
  /// Ends the stream and waits for its thread. Returns why it ended if not asked to (the server
  /// went away, refused the rate...), empty otherwise.
  std::string stopStateStream();

private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

} // namespace proxima
