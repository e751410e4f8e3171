#include "Net/RemoteRuns.h"

#include "IO/InputChecks/InputError.h"
#include "Net/Private/RunRequestPlay.h"

#include "proxima_remote.grpc.pb.h"

#include <grpcpp/grpcpp.h>

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
    if (!tokenAccepted(*context))
    {
      return {grpc::StatusCode::UNAUTHENTICATED, "the server refused the token (missing or wrong)"};
    }
    return playRunRequest(
      *request, m_limits, [&](const net::RunReply& reply) { return writer->Write(reply); },
      [&] { return context->IsCancelled(); });
  }

private:
  bool tokenAccepted(const grpc::ServerContext& context) const
  {
    if (m_token.empty())
    {
      return true;
    }
    const auto& metadata = context.client_metadata();
    const auto found = metadata.find("proxima-token");
    if (found == metadata.end() || found->second.size() != m_token.size())
    {
      return false;
    }
    // Every character compared, whatever differs first: no timing hint of a partial match.
    unsigned difference = 0;
    for (std::size_t i = 0; i < m_token.size(); ++i)
    {
      difference |= static_cast<unsigned char>(found->second.data()[i]) ^
                    static_cast<unsigned char>(m_token[i]);
    }
    return difference == 0;
  }

  std::string m_token;
  RunLimits m_limits;
};
} // namespace

struct RemoteRunServer::Impl
{
  std::unique_ptr<RemoteRunsService> service;
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
  grpc::ServerBuilder builder;
  builder.AddListeningPort(settings.listen, grpc::InsecureServerCredentials(), &m_impl->port);
  builder.SetMaxReceiveMessageSize(static_cast<int>(settings.maxRequestBytes));
  builder.RegisterService(m_impl->service.get());
  m_impl->server = builder.BuildAndStart();
  if (!m_impl->server || m_impl->port == 0)
  {
    throw InputError("--listen", "cannot listen on " + settings.listen +
                                   " (a HOST:PORT that is free and this machine's)");
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
  if (m_impl->server)
  {
    m_impl->server->Shutdown();
  }
}

void RemoteRunServer::wait()
{
  m_impl->server->Wait();
}

} // namespace proxima
