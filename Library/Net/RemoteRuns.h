// Remote scripted runs over gRPC (Documentation/Server.md; paper section 7's split between the
// haptic server and the application's computer): a server that plays paths in lockstep for its
// clients, and the client call that sends a run and receives its ticks. The protocol is
// proxima_remote.proto; gRPC and protobuf stay in this layer's .cpp files.
#pragma once

#include "IO/ScriptedRun/ScriptedRun.h"
#include "IO/ScriptedRun/ScriptedRunSettings.h"
#include "Net/ServerConnection.h"
#include "Proxy/ProxyParameters.h"
#include "Runtime/HapticState.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace proxima
{

class ThreadedRuntime;

/// How RemoteRunServer serves (`proxima serve`): where it listens, the token and TLS it asks of
/// clients, its limits, and the live haptic service it may offer beside remote runs.
struct RemoteServerSettings
{
  /// HOST:PORT; port 0 takes a free one (RemoteRunServer::port says which).
  std::string listen = "127.0.0.1:50051";
  /// The token clients must send; empty for none, which only a loopback address may have.
  std::string token;
  /// TLS (`proxima serve --tls-cert --tls-key`): the server's PEM certificate chain and private
  /// key. Empty: a plain channel.
  std::string tlsCertificateChain;
  /// The PEM private key of the chain's certificate; unused when the chain is empty.
  std::string tlsPrivateKey;
  /// The largest request taken (its mesh, path and texture files together).
  std::size_t maxRequestBytes = std::size_t{512} << 20;
  /// The most ticks one run may take: a client's --max-ticks above it is lowered to it, and a
  /// path that needs more ticks than that is refused before it is played.
  double maxTicks = 1e7;
  /// The live haptic service (proxima_haptic.proto, Net/HapticClient.h) on the same port: with
  /// a runtime (the server's device and threads, which must outlive the server), clients upload
  /// models into it and follow its state. Null serves remote runs only.
  ThreadedRuntime* runtime = nullptr;
  /// The proxy of the uploaded models (radius, skin, iteration cap).
  ProxyParameters liveProxy;
  /// The servo's kp (N/m), at which an uploaded scene's bodies are coupled to the proxy.
  double liveStiffness = 1000.0;
  /// The servo's rate (Hz), at which an uploaded scene's bodies are coupled to the proxy.
  double liveRate = 1000.0;
  /// The most triangles (and points) of one uploaded model.
  std::uint64_t maxModelTriangles = 20'000'000;
};

/// The port a --listen address without one takes (Documentation/Server.md).
inline constexpr int kDefaultListenPort = 50051;

/// A --listen address, checked.
struct ListenAddress
{
  /// As given: a name, an IPv4 address, or an IPv6 address in brackets ("[::1]").
  std::string host;
  /// 0 to 65535; 0 takes a free one.
  int port = kDefaultListenPort;
  /// The host is this machine's loopback: localhost, any address of 127.0.0.0/8, ::1 (also as
  /// an IPv4-mapped 127 address).
  bool loopback = false;

  /// "HOST:PORT", as gRPC binds it.
  std::string hostAndPort() const { return host + ":" + std::to_string(port); }
};

/// Reads `HOST:PORT`, `[IPV6]:PORT`, or a host alone, which takes kDefaultListenPort. Throws
/// InputError naming --listen for an empty host, a port that is not a whole number from 0 to
/// 65535 (gRPC would wrap 99999 to 34463, and take 443 for a missing one), or an IPv6 address
/// without brackets.
ListenAddress parseListenAddress(const std::string& text);

/// True for a loopback host (ListenAddress::loopback) with any port; false for an address that
/// parseListenAddress refuses.
bool isLoopbackAddress(const std::string& hostAndPort);

/// The server of `proxima serve`: plays the scripted runs its clients send (proxima_remote.proto)
/// in lockstep and streams their ticks back, and with RemoteServerSettings::runtime also offers
/// the live haptic service on the same port. It serves on gRPC's threads from construction until
/// shutdown.
class RemoteRunServer
{
public:
  /// Starts serving on its own threads. Throws InputError naming --listen for an address that
  /// cannot be bound, or a non-loopback one without a token.
  explicit RemoteRunServer(const RemoteServerSettings& settings);
  ~RemoteRunServer();
  RemoteRunServer(const RemoteRunServer&) = delete;
  RemoteRunServer& operator=(const RemoteRunServer&) = delete;

  /// The port bound.
  int port() const;
  /// Stops taking runs and ends those in progress (they end with an error) and the state
  /// streams.
  void shutdown();
  /// Blocks until shutdown.
  void wait();

private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

/// A scripted run for runRemotely to send: a local run's settings and files, the run's tick
/// limit, and the trace file's name for the summary.
struct RemoteRunRequest
{
  /// As a local run's: `mesh` or `scene`, `path` and `texture` name the client's files, which are
  /// sent whole (a scene with every file it names).
  ScriptedRunSettings settings;
  /// The most ticks the run may take (the client's --max-ticks, 1 or more). The server lowers it
  /// to its own limit (RemoteServerSettings::maxTicks) and refuses a path that needs more.
  double maxTicks = 1e7;
  /// The trace file the client writes, for the summary's "trace".
  std::string traceName;
};

/// Sends `request` to the server of `connection`, hands each tick to `onTick` as it arrives and
/// returns the summary. With `onBodyPose` (`--bodies-out`), the server also sends each body's
/// pose after each tick, handed to it in order (a scene without bodies is refused, as locally).
/// A server that goes away is waited for (connection.reconnect) and the run played again there
/// from its start: before any tick was handed out, always; after, only with `onRestart`, called
/// first to say that the ticks and poses handed out so far are void. Throws InputError: the
/// server's refusal of the run (the option or the client's file named, as a local run would),
/// "--server" when no server answers or it does not come back, "--token-file" when the token is
/// refused.
std::string runRemotely(const ServerConnection& connection, const RemoteRunRequest& request,
                        const std::function<void(const HapticState&)>& onTick,
                        const std::function<void(const BodyPoseRow&)>& onBodyPose = {},
                        const std::function<void()>& onRestart = {});

} // namespace proxima
