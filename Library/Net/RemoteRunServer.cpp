#include "Net/RemoteRuns.h"

#include "IO/InputChecks/InputError.h"
#include "Net/Private/LiveHapticService.h"
#include "Net/Private/RunRequestPlay.h"
#include "Net/Private/TokenCheck.h"

#include "proxima_remote.grpc.pb.h"

#include <grpcpp/grpcpp.h>

#include <arpa/inet.h>
#include <netinet/in.h>

#include <chrono>
#include <string>
#include <utility>

namespace proxima
{

namespace
{
bool isLoopbackHost(const std::string& host)
{
  if (host == "localhost")
  {
    return true;
  }
  in_addr v4{};
  if (inet_pton(AF_INET, host.c_str(), &v4) == 1)
  {
    return (ntohl(v4.s_addr) >> 24) == 127;
  }
  in6_addr v6{};
  if (host.size() > 2 && host.front() == '[' && host.back() == ']' &&
      inet_pton(AF_INET6, host.substr(1, host.size() - 2).c_str(), &v6) == 1)
  {
    // ::1, or ::ffff:127.x.y.z (an IPv4 loopback address written as IPv6).
    return IN6_IS_ADDR_LOOPBACK(&v6) || (IN6_IS_ADDR_V4MAPPED(&v6) && v6.s6_addr[12] == 127);
  }
  return false;
}
} // namespace

ListenAddress parseListenAddress(const std::string& text)
{
  const auto refuse = [&](const std::string& defect) {
    throw InputError("--listen", "'" + text + "' " + defect);
  };
  ListenAddress address;
  std::string port;
  bool hasPort = false;
  if (!text.empty() && text.front() == '[')
  {
    const std::size_t close = text.find(']');
    if (close == std::string::npos)
    {
      refuse("has no ']' after its IPv6 address: give [ADDRESS]:PORT, as [::1]:50051");
    }
    address.host = text.substr(0, close + 1);
    if (close + 1 < text.size())
    {
      if (text[close + 1] != ':')
      {
        refuse("has something other than ':PORT' after ']'");
      }
      hasPort = true;
      port = text.substr(close + 2);
    }
  }
  else
  {
    const std::size_t colon = text.find(':');
    if (colon != std::string::npos && text.find(':', colon + 1) != std::string::npos)
    {
      refuse("has more than one ':': write an IPv6 address in brackets, as [::1]:50051");
    }
    address.host = text.substr(0, colon);
    if (colon != std::string::npos)
    {
      hasPort = true;
      port = text.substr(colon + 1);
    }
  }
  if (address.host.empty() || address.host == "[]")
  {
    refuse("has no host: give HOST:PORT, as 127.0.0.1:50051");
  }
  if (hasPort)
  {
    if (port.empty() || port.find_first_not_of("0123456789") != std::string::npos)
    {
      refuse("has no port number after ':': give a whole number from 0 to 65535 (0 takes a free "
             "one), or no ':' for " +
             std::to_string(kDefaultListenPort));
    }
    const std::size_t digits = port.find_first_not_of('0');
    if (digits != std::string::npos && (port.size() - digits > 5 || std::stoi(port) > 65535))
    {
      refuse("has port " + port + ", out of range: give 0 to 65535 (0 takes a free one)");
    }
    address.port = digits == std::string::npos ? 0 : std::stoi(port);
  }
  address.loopback = isLoopbackHost(address.host);
  return address;
}

bool isLoopbackAddress(const std::string& hostAndPort)
{
  try
  {
    return parseListenAddress(hostAndPort).loopback;
  }
  catch (const InputError&)
  {
    return false;
  }
}

namespace
{
class RemoteRunsService final : public net::RemoteRuns::Service
{
public:
  RemoteRunsService(std::string token, const RunLimits& limits)
    : m_token(std::move(token))
    , m_limits(limits)
  {}

  grpc::Status Run(grpc::ServerContext* context, const net::RunRequest* request,
                   grpc::ServerWriter<net::RunReply>* writer) override
  {
    if (!detail::tokenAccepted(*context, m_token))
    {
      return {grpc::StatusCode::UNAUTHENTICATED, "the server refused the token (missing or wrong)"};
    }
    return playRunRequest(
      *request, m_limits, [&](const net::RunReply& reply) { return writer->Write(reply); },
      [&] { return context->IsCancelled(); });
  }

private:
  std::string m_token;
  RunLimits m_limits;
};
} // namespace

struct RemoteRunServer::Impl
{
  std::unique_ptr<RemoteRunsService> service;
  std::unique_ptr<detail::LiveHapticService> live;
  std::unique_ptr<grpc::Server> server;
  int port = 0;
};

RemoteRunServer::RemoteRunServer(const RemoteServerSettings& settings)
  : m_impl(std::make_unique<Impl>())
{
  const ListenAddress address = parseListenAddress(settings.listen);
  if (settings.token.empty() && !address.loopback)
  {
    throw InputError("--listen", settings.listen +
                                   " is not a loopback address: give --token-file, which every "
                                   "client must then send");
  }
  m_impl->service =
    std::make_unique<RemoteRunsService>(settings.token, RunLimits{settings.maxTicks});
  const bool tls = !settings.tlsCertificateChain.empty();
  std::shared_ptr<grpc::ServerCredentials> credentials = grpc::InsecureServerCredentials();
  if (tls)
  {
    grpc::SslServerCredentialsOptions options;
    options.pem_key_cert_pairs.push_back({settings.tlsPrivateKey, settings.tlsCertificateChain});
    credentials = grpc::SslServerCredentials(options);
  }
  grpc::ServerBuilder builder;
  builder.AddListeningPort(address.hostAndPort(), credentials, &m_impl->port);
  builder.SetMaxReceiveMessageSize(static_cast<int>(settings.maxRequestBytes));
  builder.RegisterService(m_impl->service.get());
  if (settings.runtime != nullptr)
  {
    detail::ModelLimits limits;
    limits.maxTriangles = settings.maxModelTriangles;
    limits.maxPoints = settings.maxModelTriangles;
    m_impl->live = std::make_unique<detail::LiveHapticService>(
      *settings.runtime, settings.liveProxy, settings.liveStiffness, settings.liveRate,
      settings.token, limits);
    builder.RegisterService(m_impl->live.get());
  }
  m_impl->server = builder.BuildAndStart();
  if (!m_impl->server || m_impl->port == 0)
  {
    throw InputError("--listen", "cannot listen on " + settings.listen +
                                   (tls ? " with the TLS certificate and key given (a HOST:PORT "
                                          "that is free and this machine's, and a key that "
                                          "matches the certificate)"
                                        : " (a HOST:PORT that is free and this machine's)"));
  }
}

RemoteRunServer::~RemoteRunServer()
{
  shutdown();
}

int RemoteRunServer::port() const
{
  return m_impl->port;
}

void RemoteRunServer::shutdown()
{
  if (m_impl->live)
  {
    m_impl->live->stop();
  }
  if (m_impl->server)
  {
    // The state streams see the stop within a sample; a call still running after 2 s is
    // cancelled.
    m_impl->server->Shutdown(std::chrono::system_clock::now() + std::chrono::seconds(2));
  }
}

void RemoteRunServer::wait()
{
  m_impl->server->Wait();
}

} // namespace proxima
