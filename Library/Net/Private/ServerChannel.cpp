#include "Net/Private/ServerChannel.h"

#include "IO/InputChecks/InputError.h"

#include <grpcpp/grpcpp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

namespace proxima::detail
{

namespace
{
int milliseconds(std::chrono::milliseconds duration)
{
  return static_cast<int>(std::clamp<std::chrono::milliseconds::rep>(
    duration.count(), 1, std::numeric_limits<int>::max()));
}
} // namespace

std::shared_ptr<grpc::Channel> connectToServer(const ServerConnection& connection)
{
  const std::string& server = connection.server;
  grpc::ChannelArguments arguments;
  arguments.SetMaxSendMessageSize(std::numeric_limits<int>::max());
  arguments.SetMaxReceiveMessageSize(std::numeric_limits<int>::max());
  // gRPC's own reconnection after the connection drops (its defaults start at 1 s and grow to
  // 120 s: a restarted server would wait that long to be seen).
  arguments.SetInt(GRPC_ARG_INITIAL_RECONNECT_BACKOFF_MS,
                   milliseconds(connection.reconnect.firstBackoff));
  arguments.SetInt(
    GRPC_ARG_MAX_RECONNECT_BACKOFF_MS,
    milliseconds(std::max(connection.reconnect.maxBackoff, connection.reconnect.firstBackoff)));
  const bool tls = !connection.tlsRootCertificates.empty();
  std::shared_ptr<grpc::ChannelCredentials> credentials = grpc::InsecureChannelCredentials();
  if (tls)
  {
    grpc::SslCredentialsOptions options;
    options.pem_root_certs = connection.tlsRootCertificates;
    credentials = grpc::SslCredentials(options);
  }
  auto channel = grpc::CreateCustomChannel(server, credentials, arguments);
  // A refused connection (nothing listens there) is known at once: gRPC's channel goes to
  // TRANSIENT_FAILURE and would retry with backoff until the deadline, so the client stops at the
  // first failure rather than waiting out the 10 s left for a slow network to connect.
  const auto deadline = std::chrono::system_clock::now() + connection.connectTimeout;
  for (grpc_connectivity_state state = channel->GetState(true); state != GRPC_CHANNEL_READY;
       state = channel->GetState(true))
  {
    if (state == GRPC_CHANNEL_TRANSIENT_FAILURE || state == GRPC_CHANNEL_SHUTDOWN)
    {
      throw ServerUnavailable(
        "--server", "no Proxima server answers at " + server +
                      (tls ? " over TLS (the connection or the handshake failed: is `proxima "
                             "serve --tls-cert` running there, with a certificate for that "
                             "name signed by --tls-ca?)"
                           : " (the connection failed: is `proxima serve` running there?)"));
    }
    if (!channel->WaitForStateChange(state, deadline))
    {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.3g s",
                    std::chrono::duration<double>(connection.connectTimeout).count());
      throw ServerUnavailable("--server", "no Proxima server answers at " + server + " within " +
                                            seconds + " (is `proxima serve` running there?)");
    }
  }
  return channel;
}

Reconnection::Reconnection(const ServerConnection& connection, grpc::Channel& channel)
  : m_policy(connection.reconnect)
  , m_server(connection.server)
  , m_channel(channel)
{}

bool Reconnection::failed()
{
  const auto now = std::chrono::system_clock::now();
  if (!m_waiting)
  {
    m_waiting = true;
    m_deadline = now + m_policy.maxWait;
    m_backoff = m_policy.firstBackoff;
  }
  if (m_policy.maxWait.count() <= 0 || now >= m_deadline)
  {
    return false;
  }
  ++m_retries;
  return true;
}

void Reconnection::pauseWhileReady()
{
  if (m_channel.GetState(false) == GRPC_CHANNEL_READY)
  {
    // The call failed on a connection that still looks ready (the server was closing it): give
    // the channel until the next backoff to notice, so that calls are not made again at once.
    m_channel.WaitForStateChange(
      GRPC_CHANNEL_READY, std::min(std::chrono::system_clock::now() + m_backoff, m_deadline));
    m_backoff = std::min(m_backoff * 2, m_policy.maxBackoff);
  }
}

bool Reconnection::waitForServer()
{
  pauseWhileReady();
  // gRPC connects again on its own backoff (connectToServer's channel arguments); this wakes on
  // its state changes, and at the deadline.
  return m_channel.WaitForConnected(m_deadline);
}

std::string Reconnection::gaveUp(const std::string& lastError) const
{
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.3g s",
                std::chrono::duration<double>(m_policy.maxWait).count());
  if (m_policy.maxWait.count() <= 0)
  {
    return "the server at " + m_server + " went away (" + lastError + ")";
  }
  return "the server at " + m_server + " went away and did not come back within " + seconds + " (" +
         lastError + "; --reconnect SECONDS waits longer)";
}

} // namespace proxima::detail
