#include "Net/HapticClient.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/MeshReader.h"
#include "Net/Private/SceneBundlePacking.h"
#include "Net/Private/ServerChannel.h"
#include "Net/Private/TokenCheck.h"

#include "proxima_haptic.grpc.pb.h"

#include <grpcpp/grpcpp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace proxima
{

namespace
{
// A's motion after B's: p -> A(B(p)).
RigidTransform compose(const RigidTransform& a, const RigidTransform& b)
{
  RigidTransform out;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.row[r][c] =
        a.row[r].x * b.row[0][c] + a.row[r].y * b.row[1][c] + a.row[r].z * b.row[2][c];
    }
  }
  out.translation = a.apply(b.translation);
  return out;
}

// At most this many points or triangles in one message (a few megabytes): a model of any size
// goes as a stream of bounded messages.
constexpr std::size_t kPartItems = 65536;

Vec3 fromMessage(const net::Vector3& v)
{
  return Vec3{v.x(), v.y(), v.z()};
}

struct PendingShape
{
  std::string name;
  ShapeMaterialSpec material;
  TriangleSoup soup;
};

void throwForStatus(const grpc::Status& status, const std::string& server)
{
  switch (status.error_code())
  {
    case grpc::StatusCode::OK: return;
    case grpc::StatusCode::INVALID_ARGUMENT: throw std::invalid_argument(status.error_message());
    case grpc::StatusCode::UNAUTHENTICATED:
      throw ServerRefused("--token-file", status.error_message());
    case grpc::StatusCode::FAILED_PRECONDITION:
      throw ServerRefused("--server", "the server at " + server + ": " + status.error_message());
    case grpc::StatusCode::UNIMPLEMENTED:
      throw ServerUnavailable("--server",
                              "the server at " + server +
                                " owns no device (start it with proxima serve --device)");
    case grpc::StatusCode::UNAVAILABLE:
      throw ServerUnavailable("--server", "the server at " + server + " went away (" +
                                            status.error_message() + ")");
    default:
      throw std::runtime_error("the server at " + server + " failed: " + status.error_message());
  }
}
} // namespace

struct HapticClient::Impl
{
  ServerConnection connection;
  std::string server;
  std::string token;
  HapticClientRole role = HapticClientRole::Owner;
  std::shared_ptr<grpc::Channel> channel;
  std::unique_ptr<net::HapticServer::Stub> stub;
  // The ownership call, held open for the ownership's life (proxima_haptic.proto's
  // HoldOwnership), and the thread that waits for its end: the server never writes on it after
  // the grant, so its end (the connection dropped, the server stopped or restarted) is the
  // moment this client stops owning the model.
  std::unique_ptr<grpc::ClientContext> ownershipContext;
  std::unique_ptr<grpc::ClientReaderWriter<net::OwnershipRequest, net::OwnershipGrant>>
    ownershipCall;
  std::thread ownershipWatch;
  std::string ownerKey;
  mutable std::mutex ownershipMutex;
  bool owns = false;
  bool releasing = false;
  bool callEnding = false;
  std::string ownershipEnd;

  std::vector<RigidTransform> stack{RigidTransform{}};
  ShapeMaterialSpec material;
  std::vector<PendingShape> shapes;
  /// A scene file to send as the whole model instead of shapes.
  std::unique_ptr<net::SceneBundle> scene;
  bool inShape = false;
  bool haveNormal = false;
  bool haveTexCoord = false;
  Vec3 currentNormal;
  TexCoord currentTexCoord;

  std::thread streamThread;
  // The stream's call of the moment (a new one after each reconnection), which stopStateStream
  // cancels.
  std::unique_ptr<grpc::ClientContext> streamContext;
  mutable std::mutex streamMutex;
  std::string streamEnd;
  bool stopAsked = false;
  std::uint32_t streamReconnections = 0;

  // waitForEnd's: the stream's and the ownership's ends are told here, after their own state.
  std::mutex endMutex;
  std::condition_variable endChanged;
  bool interrupted = false;
  void notifyEnd()
  {
    const std::lock_guard<std::mutex> lock(endMutex);
    endChanged.notify_all();
  }

  void addToken(grpc::ClientContext& context) const
  {
    if (!token.empty())
    {
      context.AddMetadata(detail::kTokenMetadata, token);
    }
  }
  // One HoldOwnership call: OK once the server has granted the ownership (and the watch runs).
  grpc::Status tryHoldOwnership()
  {
    ownershipContext = std::make_unique<grpc::ClientContext>();
    addToken(*ownershipContext);
    ownershipCall = stub->HoldOwnership(ownershipContext.get());
    net::OwnershipGrant grant;
    if (ownershipCall->Read(&grant))
    {
      const std::lock_guard<std::mutex> lock(ownershipMutex);
      ownerKey = grant.key();
      owns = true;
      releasing = false;
      callEnding = false;
      ownershipEnd.clear();
      ownershipWatch = std::thread([this] { watchOwnership(); });
      return grpc::Status::OK;
    }
    grpc::Status status = ownershipCall->Finish();
    ownershipCall.reset();
    return status.ok() ? grpc::Status(grpc::StatusCode::UNKNOWN,
                                      "the server ended the ownership call at once")
                       : status;
  }
  // Claims the ownership; with `retry`, waits for a server that went away to come back
  // (connection.reconnect). Throws InputError naming --server when it is refused or the server
  // does not come back.
  void holdOwnership(bool retry)
  {
    detail::Reconnection reconnection(connection, *channel);
    for (;;)
    {
      const grpc::Status status = tryHoldOwnership();
      if (status.ok())
      {
        return;
      }
      if (status.error_code() == grpc::StatusCode::UNAVAILABLE && retry)
      {
        if (reconnection.failed() && reconnection.waitForServer())
        {
          continue;
        }
        throw ServerUnavailable("--server", reconnection.gaveUp(status.error_message()));
      }
      if (status.error_code() == grpc::StatusCode::FAILED_PRECONDITION)
      {
        throw ServerRefused("--server",
                            "the server at " + server +
                              " refused to make this client the owner: " + status.error_message());
      }
      throwForStatus(status, server);
      throw std::runtime_error("the server at " + server + " failed: " + status.error_message());
    }
  }
  // On the watch's thread: returns when the ownership call ends.
  void watchOwnership()
  {
    net::OwnershipGrant more;
    while (ownershipCall->Read(&more))
    {}
    {
      // From here on releaseOwnership does not touch the call: no WritesDone after Finish.
      const std::lock_guard<std::mutex> lock(ownershipMutex);
      callEnding = true;
    }
    const grpc::Status status = ownershipCall->Finish();
    {
      const std::lock_guard<std::mutex> lock(ownershipMutex);
      owns = false;
      if (!releasing && ownershipEnd.empty())
      {
        ownershipEnd = "its ownership ended when its connection to the server dropped (" +
                       (status.ok() ? std::string("the server stopped") : status.error_message()) +
                       "): the server went away or restarted, and a restarted proxima serve "
                       "starts without the model";
      }
    }
    notifyEnd();
  }
  void releaseOwnership()
  {
    if (ownershipCall)
    {
      {
        const std::lock_guard<std::mutex> lock(ownershipMutex);
        releasing = true;
        if (!callEnding)
        {
          // Ends this side; the call ends when the server has let go, so that another client may
          // own the model as soon as this returns (or at once, when the server has gone).
          ownershipCall->WritesDone();
        }
      }
      ownershipWatch.join();
      ownershipCall.reset();
    }
  }
  bool ownsModel() const
  {
    const std::lock_guard<std::mutex> lock(ownershipMutex);
    return owns;
  }
  // Throws OwnershipEnded; from then on this client does not own the model, whatever its watch
  // has seen yet (the server's refusal of its key can come first).
  [[noreturn]] void throwOwnershipEnded(const std::string& why)
  {
    {
      const std::lock_guard<std::mutex> lock(ownershipMutex);
      owns = false;
      if (ownershipEnd.empty())
      {
        ownershipEnd = why;
      }
    }
    notifyEnd();
    throw OwnershipEnded("--server", "the server at " + server +
                                       ": this client no longer owns the model: " + why +
                                       " (claimOwnership() claims it again, if no other client "
                                       "has; then commit the model again)");
  }
  // One UploadModel call with the pending shapes or scene.
  grpc::Status sendModel(net::ModelReceipt& receipt)
  {
    grpc::ClientContext context;
    addToken(context);
    {
      const std::lock_guard<std::mutex> lock(ownershipMutex);
      context.AddMetadata(detail::kOwnerMetadata, ownerKey);
    }
    const auto writer = stub->UploadModel(&context, &receipt);
    bool open = true;
    if (scene)
    {
      net::ModelUpload upload;
      *upload.mutable_scene() = *scene;
      open = writer->Write(upload);
    }
    for (std::size_t index = 0; open && index < shapes.size(); ++index)
    {
      const PendingShape& shape = shapes[index];
      const TriangleSoup& soup = shape.soup;
      const std::size_t parts = std::max<std::size_t>(
        1, (std::max(soup.points.size(), soup.triangles.size()) + kPartItems - 1) / kPartItems);
      for (std::size_t p = 0; open && p < parts; ++p)
      {
        net::ModelUpload upload;
        net::ShapePart& part = *upload.mutable_shape();
        part.set_shape(static_cast<std::uint32_t>(index));
        if (p == 0)
        {
          part.set_name(shape.name);
          net::ShapeMaterial& sent = *part.mutable_material();
          sent.set_stiffness(shape.material.stiffness);
          sent.set_static_friction(shape.material.staticFriction);
          sent.set_dynamic_friction(shape.material.dynamicFriction);
          sent.set_viscosity(shape.material.viscosity);
        }
        const std::size_t begin = p * kPartItems;
        for (std::size_t i = begin; i < std::min(soup.points.size(), begin + kPartItems); ++i)
        {
          part.add_points(soup.points[i].x);
          part.add_points(soup.points[i].y);
          part.add_points(soup.points[i].z);
          if (!soup.pointNormals.empty())
          {
            part.add_normals(soup.pointNormals[i].x);
            part.add_normals(soup.pointNormals[i].y);
            part.add_normals(soup.pointNormals[i].z);
          }
          if (!soup.texCoords.empty())
          {
            part.add_texture_coordinates(soup.texCoords[i].u);
            part.add_texture_coordinates(soup.texCoords[i].v);
          }
        }
        for (std::size_t i = begin; i < std::min(soup.triangles.size(), begin + kPartItems); ++i)
        {
          for (const std::uint32_t corner : soup.triangles[i])
          {
            part.add_triangles(corner);
          }
        }
        open = writer->Write(upload);
      }
    }
    if (open)
    {
      net::ModelUpload commit;
      commit.set_commit(true);
      writer->Write(commit);
    }
    writer->WritesDone();
    return writer->Finish();
  }
  RigidTransform& top() { return stack.back(); }
  void refuseBesideScene(const char* call) const
  {
    if (scene)
    {
      throw std::logic_error(std::string("HapticClient::") + call +
                             ": a scene file is the whole model until it is committed");
    }
  }
  PendingShape& shape()
  {
    if (!inShape)
    {
      throw std::logic_error("HapticClient: vertices, normals and triangles go between "
                             "beginShape and endShape");
    }
    return shapes.back();
  }
};

HapticClient::HapticClient(const std::string& server, const std::string& token)
  : HapticClient(ServerConnection{server, token, {}})
{}

HapticClient::HapticClient(const ServerConnection& connection, HapticClientRole role)
  : m_impl(std::make_unique<Impl>())
{
  m_impl->connection = connection;
  m_impl->server = connection.server;
  m_impl->token = connection.token;
  m_impl->role = role;
  m_impl->channel = detail::connectToServer(connection);
  m_impl->stub = net::HapticServer::NewStub(m_impl->channel);
  if (role == HapticClientRole::Owner)
  {
    // The server has just answered: a refusal now is not a restart to wait out.
    m_impl->holdOwnership(false);
  }
}

HapticClient::~HapticClient()
{
  stopStateStream();
  m_impl->releaseOwnership();
}

bool HapticClient::ownsModel() const
{
  return m_impl->ownsModel();
}

std::string HapticClient::ownershipEnd() const
{
  const std::lock_guard<std::mutex> lock(m_impl->ownershipMutex);
  return m_impl->ownershipEnd;
}

void HapticClient::claimOwnership()
{
  if (m_impl->role == HapticClientRole::Observer)
  {
    throw std::logic_error("HapticClient::claimOwnership: this client observes");
  }
  if (m_impl->ownsModel())
  {
    return;
  }
  // The old call has ended (its watch saw it): join its thread before the next call's.
  m_impl->releaseOwnership();
  m_impl->holdOwnership(true);
}

HapticClientRole HapticClient::role() const
{
  return m_impl->role;
}

void HapticClient::loadIdentity()
{
  m_impl->top() = RigidTransform{};
}

void HapticClient::pushMatrix()
{
  m_impl->stack.push_back(m_impl->top());
}

void HapticClient::popMatrix()
{
  if (m_impl->stack.size() == 1)
  {
    throw std::logic_error("HapticClient::popMatrix: more pops than pushes");
  }
  m_impl->stack.pop_back();
}

void HapticClient::multMatrix(const RigidTransform& transform)
{
  m_impl->top() = compose(m_impl->top(), transform);
}

void HapticClient::translate(const Vec3& offset)
{
  RigidTransform move;
  move.translation = offset;
  multMatrix(move);
}

void HapticClient::rotate(double degrees, const Vec3& axis)
{
  const double length = norm(axis);
  if (!(length > 0.0))
  {
    throw std::invalid_argument("HapticClient::rotate: the axis is zero");
  }
  const double half = degrees * M_PI / 360.0;
  const Vec3 a = axis * (std::sin(half) / length);
  multMatrix(RigidTransform::fromQuaternion(std::cos(half), a.x, a.y, a.z, Vec3{}));
}

void HapticClient::material(const ShapeMaterialSpec& material)
{
  m_impl->material = material;
}

void HapticClient::beginShape(const std::string& name)
{
  if (m_impl->inShape)
  {
    throw std::logic_error("HapticClient::beginShape: the last shape was not ended");
  }
  m_impl->refuseBesideScene("beginShape");
  m_impl->shapes.push_back(PendingShape{name, m_impl->material, {}});
  m_impl->inShape = true;
  m_impl->haveNormal = false;
  m_impl->haveTexCoord = false;
}

void HapticClient::normal(const Vec3& normal)
{
  m_impl->shape();
  m_impl->currentNormal = m_impl->top().rotate(normal);
  m_impl->haveNormal = true;
}

void HapticClient::texCoord(double u, double v)
{
  m_impl->shape();
  m_impl->currentTexCoord = TexCoord{u, v};
  m_impl->haveTexCoord = true;
}

void HapticClient::vertex(const Vec3& position)
{
  TriangleSoup& soup = m_impl->shape().soup;
  soup.points.push_back(m_impl->top().apply(position));
  if (m_impl->haveNormal)
  {
    soup.pointNormals.push_back(m_impl->currentNormal);
  }
  if (m_impl->haveTexCoord)
  {
    soup.texCoords.push_back(m_impl->currentTexCoord);
  }
}

void HapticClient::triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
  m_impl->shape().soup.triangles.push_back({a, b, c});
}

void HapticClient::endShape()
{
  m_impl->shape();
  m_impl->inShape = false;
}

void HapticClient::mesh(const std::string& file, double scale, const std::string& name)
{
  if (m_impl->inShape)
  {
    throw std::logic_error("HapticClient::mesh: inside a shape");
  }
  m_impl->refuseBesideScene("mesh");
  TriangleSoup soup = readMeshFile(file, scale);
  for (Vec3& point : soup.points)
  {
    point = m_impl->top().apply(point);
  }
  for (Vec3& normal : soup.pointNormals)
  {
    normal = m_impl->top().rotate(normal);
  }
  m_impl->shapes.push_back(
    PendingShape{name.empty() ? file : name, m_impl->material, std::move(soup)});
}

void HapticClient::scene(const std::string& file)
{
  if (m_impl->inShape || !m_impl->shapes.empty())
  {
    throw std::logic_error("HapticClient::scene: a scene file is the whole model, and shapes "
                           "are pending");
  }
  m_impl->scene = std::make_unique<net::SceneBundle>(detail::packSceneFile(file));
}

std::size_t HapticClient::pendingShapes() const
{
  return m_impl->shapes.size();
}

ModelReceiptInfo HapticClient::commit()
{
  if (m_impl->inShape)
  {
    throw std::logic_error("HapticClient::commit: the last shape was not ended");
  }
  if (m_impl->role == HapticClientRole::Observer)
  {
    throw std::logic_error("HapticClient::commit: this client observes; only the owner changes "
                           "the model");
  }
  if (!m_impl->ownsModel())
  {
    m_impl->throwOwnershipEnded(ownershipEnd());
  }
  // A server that goes away during the upload (its connection drops) leaves its model as it was;
  // once it answers again, the upload is made again. A server that restarted has lost this
  // client's ownership with its connection, and refuses it in words.
  detail::Reconnection reconnection(m_impl->connection, *m_impl->channel);
  net::ModelReceipt receipt;
  for (;;)
  {
    const grpc::Status status = m_impl->sendModel(receipt);
    if (status.error_code() == grpc::StatusCode::UNAVAILABLE)
    {
      if (!reconnection.failed() || !reconnection.waitForServer())
      {
        throw ServerUnavailable("--server", reconnection.gaveUp(status.error_message()));
      }
      if (!m_impl->ownsModel())
      {
        // Connected again: the watch has seen the ownership call end with the old connection.
        m_impl->throwOwnershipEnded(ownershipEnd());
      }
      continue;
    }
    if (status.error_code() == grpc::StatusCode::FAILED_PRECONDITION)
    {
      // An owner's upload always carries its key: the server no longer takes it.
      m_impl->throwOwnershipEnded("the server refused its key (its connection dropped, or the "
                                  "server restarted, since the server granted it)");
    }
    throwForStatus(status, m_impl->server);
    break;
  }
  m_impl->shapes.clear();
  m_impl->scene.reset();
  ModelReceiptInfo info;
  info.version = receipt.version();
  info.shapes = receipt.shapes();
  info.triangles = receipt.triangles();
  info.buildMilliseconds = receipt.build_ms();
  info.liveMilliseconds = receipt.live_ms();
  return info;
}

void HapticClient::startStateStream(double rateHz, std::function<void(const LiveSample&)> onSample,
                                    std::function<void(const TouchChange&)> onTouch)
{
  stopStateStream();
  Impl& impl = *m_impl;
  {
    const std::lock_guard<std::mutex> lock(impl.streamMutex);
    impl.stopAsked = false;
    impl.streamEnd.clear();
    impl.streamReconnections = 0;
  }
  impl.streamThread =
    std::thread([&impl, rateHz, onSample = std::move(onSample), onTouch = std::move(onTouch)] {
      net::StateRequest request;
      request.set_rate_hz(rateHz);
      const auto deliver = [&](const net::StateSample& message, std::uint32_t reconnections) {
        LiveSample sample;
        sample.receivedNanoseconds = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                       std::chrono::system_clock::now().time_since_epoch())
                                       .count();
        sample.sentNanoseconds = message.sent_ns();
        sample.tick = message.tick();
        sample.time = message.t();
        sample.finger = fromMessage(message.finger());
        sample.proxy = fromMessage(message.proxy());
        sample.force = fromMessage(message.force());
        sample.contacts = message.contacts();
        sample.shape = message.shape();
        sample.flags = message.flags();
        for (const net::BodyPose& body : message.bodies())
        {
          LiveBodyPose pose;
          pose.shape = body.shape();
          pose.pose.row[0] = fromMessage(body.row_x());
          pose.pose.row[1] = fromMessage(body.row_y());
          pose.pose.row[2] = fromMessage(body.row_z());
          pose.pose.translation = fromMessage(body.translation());
          sample.bodies.push_back(pose);
        }
        sample.modelVersion = message.model_version();
        sample.droppedSamples = message.dropped_samples();
        sample.reconnections = reconnections;
        if (onTouch)
        {
          for (const net::TouchEvent& event : message.events())
          {
            onTouch(TouchChange{event.shape(), event.touched(), sample.time});
          }
        }
        if (onSample)
        {
          onSample(sample);
        }
      };
      // A new call of the stream, made the one stopStateStream cancels; null once a stop was
      // asked.
      const auto newCall = [&impl]() -> grpc::ClientContext* {
        const std::lock_guard<std::mutex> lock(impl.streamMutex);
        if (impl.stopAsked)
        {
          return nullptr;
        }
        impl.streamContext = std::make_unique<grpc::ClientContext>();
        impl.addToken(*impl.streamContext);
        return impl.streamContext.get();
      };
      detail::Reconnection reconnection(impl.connection, *impl.channel);
      // A stream that ends UNAVAILABLE lost its server; one that ends CANCELLED without
      // stopStateStream asking was cancelled by the transport or the server going away (a
      // killed server's connection can end its calls either way): both wait for the server.
      const auto lostServer = [&impl](const grpc::Status& status) {
        if (status.error_code() == grpc::StatusCode::UNAVAILABLE)
        {
          return true;
        }
        const std::lock_guard<std::mutex> lock(impl.streamMutex);
        return status.error_code() == grpc::StatusCode::CANCELLED && !impl.stopAsked;
      };
      std::uint32_t reconnections = 0;
      std::string end;
      std::string lastError;
      net::StateSample message;
      for (;;)
      {
        if (reconnection.waiting())
        {
          // The server went away: wait for it on a call that waits for the connection (gRPC
          // reconnects with its backoff) until the policy gives up, or stopStateStream cancels
          // it. Its first sample says the server answers again.
          grpc::ClientContext* waiting = newCall();
          if (waiting == nullptr)
          {
            break;
          }
          waiting->set_wait_for_ready(true);
          waiting->set_deadline(reconnection.deadline());
          const auto reader = impl.stub->StreamState(waiting, request);
          const bool answered = reader->Read(&message);
          if (answered)
          {
            // The call's work is done (a new call follows); a failed one is not cancelled, so
            // that Finish reports why it failed (UNAVAILABLE is retried below), not CANCELLED.
            waiting->TryCancel();
          }
          const grpc::Status status = reader->Finish();
          if (!answered && lostServer(status) && reconnection.failed())
          {
            // Refused by a server that is closing its connection: wait for the channel to notice,
            // then wait for the server again.
            reconnection.pauseWhileReady();
            continue;
          }
          if (!answered)
          {
            end = status.error_code() == grpc::StatusCode::DEADLINE_EXCEEDED ||
                      status.error_code() == grpc::StatusCode::UNAVAILABLE
                    ? reconnection.gaveUp(lastError)
                    : "the stream failed: " + status.error_message();
            break;
          }
          reconnection.succeeded();
          ++reconnections;
          {
            const std::lock_guard<std::mutex> lock(impl.streamMutex);
            impl.streamReconnections = reconnections;
          }
          deliver(message, reconnections);
        }
        grpc::ClientContext* context = newCall();
        if (context == nullptr)
        {
          break;
        }
        const auto reader = impl.stub->StreamState(context, request);
        while (reader->Read(&message))
        {
          reconnection.succeeded();
          deliver(message, reconnections);
        }
        const grpc::Status status = reader->Finish();
        lastError = "the stream failed: " + status.error_message();
        if (lostServer(status) && reconnection.failed())
        {
          continue;
        }
        if (lostServer(status) && reconnection.waiting())
        {
          end = reconnection.gaveUp(status.error_message());
        }
        else
        {
          end = status.ok() ? "the server ended the stream"
                            : "the stream failed: " + status.error_message();
        }
        break;
      }
      {
        const std::lock_guard<std::mutex> lock(impl.streamMutex);
        if (!impl.stopAsked)
        {
          impl.streamEnd = end;
        }
      }
      impl.notifyEnd();
    });
}

std::string HapticClient::stateStreamEnd() const
{
  const std::lock_guard<std::mutex> lock(m_impl->streamMutex);
  return m_impl->streamEnd;
}

std::string HapticClient::waitForEnd(std::chrono::steady_clock::time_point deadline)
{
  const auto ended = [this] {
    const std::string stream = stateStreamEnd();
    return stream.empty() ? ownershipEnd() : stream;
  };
  std::unique_lock<std::mutex> lock(m_impl->endMutex);
  m_impl->endChanged.wait_until(lock, deadline,
                                [&] { return m_impl->interrupted || !ended().empty(); });
  return ended();
}

void HapticClient::interruptWait()
{
  const std::lock_guard<std::mutex> lock(m_impl->endMutex);
  m_impl->interrupted = true;
  m_impl->endChanged.notify_all();
}

std::uint32_t HapticClient::stateStreamReconnections() const
{
  const std::lock_guard<std::mutex> lock(m_impl->streamMutex);
  return m_impl->streamReconnections;
}

std::string HapticClient::stopStateStream()
{
  Impl& impl = *m_impl;
  if (!impl.streamThread.joinable())
  {
    return impl.streamEnd;
  }
  {
    const std::lock_guard<std::mutex> lock(impl.streamMutex);
    // Also stops a thread between two calls (reconnecting): it asks under the same lock.
    impl.stopAsked = true;
    if (impl.streamContext)
    {
      impl.streamContext->TryCancel();
    }
  }
  impl.streamThread.join();
  return impl.streamEnd;
}

} // namespace proxima
