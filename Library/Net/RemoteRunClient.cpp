#include "Net/RemoteRuns.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/InputChecks/InputError.h"
#include "Net/Private/RunSettingsMessage.h"
#include "Net/Private/SceneBundlePacking.h"
#include "Net/Private/ServerChannel.h"
#include "Net/Private/TickColumns.h"
#include "Net/Private/TokenCheck.h"

#include "proxima_remote.grpc.pb.h"

#include <grpcpp/grpcpp.h>

namespace proxima
{
namespace
{
void readFile(const std::string& path, const char* kind, net::FileContent& file)
{
  file.set_name(path);
  file.set_data(detail::readWholeFile(path, kind));
}

} // namespace

std::string runRemotely(const ServerConnection& connection, const RemoteRunRequest& request,
                        const std::function<void(const HapticState&)>& onTick,
                        const std::function<void(const BodyPoseRow&)>& onBodyPose,
                        const std::function<void()>& onRestart)
{
  const std::string& server = connection.server;
  const ScriptedRunSettings& settings = request.settings;
  // The settings are checked here first: a typo costs no upload.
  checkScriptedRunSettings(settings);
  net::RunRequest message;
  detail::writeRunSettings(settings, *message.mutable_settings());
  message.mutable_settings()->set_max_ticks(request.maxTicks);
  if (settings.scene.empty())
  {
    readFile(settings.mesh, "mesh file", *message.mutable_mesh());
  }
  else
  {
    *message.mutable_scene() = detail::packSceneFile(settings.scene);
  }
  readFile(settings.path, "finger path file", *message.mutable_path());
  if (!settings.texture.empty())
  {
    readFile(settings.texture, "texture image", *message.mutable_texture());
  }
  message.set_trace_name(request.traceName);
  message.set_bodies_out(static_cast<bool>(onBodyPose));

  const auto channel = detail::connectToServer(connection);
  const auto stub = net::RemoteRuns::NewStub(channel);
  // A server that goes away (killed, restarted) is waited for, and the run played again from its
  // start once it answers: a lockstep run gives the same ticks wherever it is played. Ticks handed
  // out before are void then, which only a caller with onRestart can say.
  detail::Reconnection reconnection(connection, *channel);
  for (;;)
  {
    grpc::ClientContext context;
    if (!connection.token.empty())
    {
      context.AddMetadata(detail::kTokenMetadata, connection.token);
    }
    std::string summary;
    std::uint64_t bodyRows = 0;
    bool handed = false;
    const auto reader = stub->Run(&context, message);
    net::RunReply reply;
    try
    {
      while (reader->Read(&reply))
      {
        reconnection.succeeded();
        if (reply.has_ticks())
        {
          handed = handed || reply.ticks().tick_size() > 0;
          forEachTick(reply.ticks(), onTick);
        }
        if (reply.has_bodies())
        {
          if (!onBodyPose)
          {
            throw std::runtime_error("the server sent body poses that were not asked for");
          }
          bodyRows += static_cast<std::uint64_t>(reply.bodies().tick_size());
          handed = handed || reply.bodies().tick_size() > 0;
          forEachBodyPose(reply.bodies(), onBodyPose);
        }
        if (reply.part_case() == net::RunReply::kSummaryJson)
        {
          summary = reply.summary_json();
        }
      }
    }
    catch (...)
    {
      // The client cannot go on (its trace cannot be written): the server stops the run.
      context.TryCancel();
      reader->Finish();
      throw;
    }
    const grpc::Status status = reader->Finish();
    switch (status.error_code())
    {
      case grpc::StatusCode::OK:
        if (summary.empty())
        {
          throw std::runtime_error("the server ended the run without its summary");
        }
        if (onBodyPose && bodyRows == 0)
        {
          // A server that does not know bodies_out plays the run and sends no poses: an empty
          // bodies file would pass for a run whose bodies never existed.
          throw std::runtime_error("the server at " + server +
                                   " sent no body poses for --bodies-out (is it older than this "
                                   "client?)");
        }
        return summary;
      case grpc::StatusCode::INVALID_ARGUMENT:
        // The server's refusal, in a local run's words: the option or the client's file, the
        // defect.
        throw InputError(status.error_details(), status.error_message());
      case grpc::StatusCode::UNAUTHENTICATED:
        throw InputError("--token-file", status.error_message());
      case grpc::StatusCode::RESOURCE_EXHAUSTED:
        throw InputError("--mesh", "the run's files are larger than the server takes (" +
                                     status.error_message() + ")");
      case grpc::StatusCode::UNAVAILABLE:
      {
        const bool restartable = !handed || static_cast<bool>(onRestart);
        if (restartable && reconnection.failed() && reconnection.waitForServer())
        {
          if (handed)
          {
            onRestart();
          }
          continue;
        }
        throw InputError("--server", restartable ? reconnection.gaveUp(status.error_message())
                                                 : "the server at " + server + " went away (" +
                                                     status.error_message() + ")");
      }
      default:
        throw std::runtime_error("the server at " + server +
                                 " failed the run: " + status.error_message());
    }
  }
}

} // namespace proxima
