#include "Net/Private/RunRequestPlay.h"

#include "IO/InputChecks/InputError.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/Scene/SceneFile.h"
#include "IO/ScriptedRun/ScriptedRun.h"
#include "Net/Private/RunFolder.h"
#include "Net/Private/RunSettingsMessage.h"
#include "Net/Private/TickColumns.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace proxima
{
namespace
{
// The client stopped reading (or went away): the run ends there.
struct ClientGone
{};

// The summary a local run would print: the client's file names where the server's stand.
std::string clientSummary(const std::string& summary, const net::RunRequest& request,
                          const detail::RunFolder& folder)
{
  auto json = nlohmann::ordered_json::parse(folder.clientWords(summary));
  json["path"] = request.path().name();
  if (json.contains("texture") && json["texture"].is_object())
  {
    json["texture"]["image"] = request.texture().name();
  }
  return json.dump(2) + "\n";
}
} // namespace

grpc::Status playRunRequest(const net::RunRequest& request, const RunLimits& limits,
                            const std::function<bool(const net::RunReply&)>& write,
                            const std::function<bool()>& cancelled)
{
  // The client's limit (its --max-ticks), within the server's own.
  const double asked = request.settings().max_ticks();
  if (!(asked >= 1.0))
  {
    return {grpc::StatusCode::INVALID_ARGUMENT,
            "must be a whole number of ticks from 1, not " + std::to_string(asked), "--max-ticks"};
  }
  const bool serverLimits = asked > limits.maxTicks;
  const double maxTicks = serverLimits ? limits.maxTicks : asked;
  const bool scene = request.has_scene();
  if (scene == (!request.mesh().name().empty() || !request.mesh().data().empty()))
  {
    return {grpc::StatusCode::INVALID_ARGUMENT,
            "a remote run needs a mesh file's contents or a scene bundle, and not both", "--mesh"};
  }
  if (request.path().name().empty())
  {
    return {grpc::StatusCode::INVALID_ARGUMENT, "a remote run needs a finger path", "--path"};
  }
  detail::RunFolder folder;
  try
  {
    ScriptedRunSettings settings;
    detail::readRunSettings(request.settings(), settings);
    if (scene)
    {
      settings.scene = folder.writeScene(request.scene());
      folder.requireBundledFiles(readSceneFile(settings.scene));
    }
    else
    {
      settings.mesh = folder.write(request.mesh().name(), request.mesh().data(), "mesh");
    }
    settings.path = folder.write(request.path().name(), request.path().data(), "path");
    if (request.has_texture())
    {
      settings.texture =
        folder.write(request.texture().name(), request.texture().data(), "texture");
    }
    const FingerPath path = readFingerPathFile(settings.path);
    ScriptedRunReportContext report;
    report.trace = request.trace_name();
    net::RunReply chunk;
    // Ticks and body poses count alike toward a message's size (a row of either is about 100
    // bytes).
    const auto rows = [&chunk] { return chunk.ticks().tick_size() + chunk.bodies().tick_size(); };
    const auto flush = [&] {
      if (rows() == 0)
      {
        return;
      }
      if (cancelled() || !write(chunk))
      {
        throw ClientGone{};
      }
      chunk.Clear();
    };
    const std::string summary = runScriptedPath(
      settings, path,
      [&](const HapticState& state) {
        appendTick(state, *chunk.mutable_ticks());
        if (rows() >= kTicksPerMessage)
        {
          flush();
        }
      },
      report, maxTicks,
      request.bodies_out()
        ? std::function<void(const BodyPoseRow&)>(
            [&chunk](const BodyPoseRow& row) { appendBodyPose(row, *chunk.mutable_bodies()); })
        : std::function<void(const BodyPoseRow&)>{});
    flush();
    net::RunReply last;
    last.set_summary_json(clientSummary(summary, request, folder));
    if (!write(last))
    {
      return {grpc::StatusCode::CANCELLED, "the client went away"};
    }
    return grpc::Status::OK;
  }
  catch (const InputError& error)
  {
    if (serverLimits && error.path() == "--max-ticks")
    {
      char limit[64];
      std::snprintf(limit, sizeof limit, "%.0f", limits.maxTicks);
      return {grpc::StatusCode::INVALID_ARGUMENT,
              folder.clientWords(request.path().name() + " needs more ticks than this server " +
                                 "plays in one run (" + limit + ", proxima serve --max-ticks)"),
              "--max-ticks"};
    }
    // The words of a local run, about the client's files.
    return {grpc::StatusCode::INVALID_ARGUMENT, folder.clientWords(error.defect()),
            folder.clientWords(error.path())};
  }
  catch (const ClientGone&)
  {
    return {grpc::StatusCode::CANCELLED, "the client stopped reading"};
  }
  catch (const std::exception& error)
  {
    return {grpc::StatusCode::INTERNAL, folder.clientWords(error.what())};
  }
}

} // namespace proxima
