#include "Net/RemoteRuns.h"

#include "IO/InputChecks/InputError.h"
#include "Net/Private/LiveHapticService.h"
#include "Net/Private/RunRequestPlay.h"
#include "Net/Private/TokenCheck.h"

#include "proxima_remote.grpc.pb.h"

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <utility>

namespace proxima
{

bool isLoopbackAddress(const std::string& hostAndPort)
{
  const std::size_t colon = hostAndPort.rfind(':');
  std::string host = colon == std::string::npos ? hostAndPort : hostAndPort.substr(0, colon);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']')
  {
    host = host.substr(1, host.size() - 2);
  }
  return host == "127.0.0.1" || host == "localhost" || host == "::1";
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
  if (settings.token.empty() && !isLoopbackAddress(settings.listen))
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
  builder.AddListeningPort(settings.listen, credentials, &m_impl->port);
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
