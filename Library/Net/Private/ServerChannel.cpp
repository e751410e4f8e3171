#include "Net/Private/ServerChannel.h"

#include "IO/InputChecks/InputError.h"

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <limits>

namespace proxima::detail
{

std::shared_ptr<grpc::Channel> connectToServer(const ServerConnection& connection)
{
  const std::string& server = connection.server;
  grpc::ChannelArguments arguments;
  arguments.SetMaxSendMessageSize(std::numeric_limits<int>::max());
  arguments.SetMaxReceiveMessageSize(std::numeric_limits<int>::max());
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
  const auto deadline = std::chrono::system_clock::now() + std::chrono::seconds(10);
  for (grpc_connectivity_state state = channel->GetState(true); state != GRPC_CHANNEL_READY;
       state = channel->GetState(true))
  {
    if (state == GRPC_CHANNEL_TRANSIENT_FAILURE || state == GRPC_CHANNEL_SHUTDOWN)
    {
      throw InputError("--server",
                       "no Proxima server answers at " + server +
                         (tls ? " over TLS (the connection or the handshake failed: is `proxima "
                                "serve --tls-cert` running there, with a certificate for that "
                                "name signed by --tls-ca?)"
                              : " (the connection failed: is `proxima serve` running there?)"));
    }
    if (!channel->WaitForStateChange(state, deadline))
    {
      throw InputError("--server", "no Proxima server answers at " + server +
                                     " within 10 s (is `proxima serve` running there?)");
    }
  }
  return channel;
}

} // namespace proxima::detail
