// `proxima remote --server HOST:PORT run ...`: `proxima run`'s options, played by a
// `proxima serve` elsewhere (Documentation/Server.md). The mesh, path and texture files are sent
// whole; the server plays the path in lockstep and streams the ticks back, which are written here
// as a local run writes them: the same trace, bit for bit but for solve_ns.
// `proxima remote --server HOST:PORT upload --mesh FILE ...`: the live server's client from the
// shell (Net/HapticClient.h): the meshes become the model of a `proxima serve --device`, and
// with --follow its state is streamed back for a while and written as CSV.
#include "Command.h"
#include "SceneOptions.h"
#include "PemFile.h"
#include "TokenFile.h"
#include "Validators.h"

#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/BodyPoseWriter.h"
#include "IO/PathAndTrace/TraceWriter.h"
#include "Net/HapticClient.h"
#include "Net/RemoteRuns.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

namespace proxima::cli
{
namespace
{
struct RemoteOptions
{
  std::string server;
  std::string tokenFile;
  std::string tlsRoots;
  SceneOptions scene;
  std::string out;
  std::string summary;
  std::string bodiesOut;
  double maxTicks = kDefaultMaxTicks;
  // upload
  std::vector<std::string> meshes;
  std::string uploadScene;
  double scale = 1.0;
  double follow = 0.0;
  double sampleRate = 100.0;
  std::string stateOut;
};

// One row of the state CSV.
std::string stateRow(const LiveSample& s)
{
  char row[512];
  std::snprintf(
    row, sizeof row,
    "%llu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%u,%llu,%llu\n",
    static_cast<unsigned long long>(s.tick), s.time, s.finger.x, s.finger.y, s.finger.z, s.proxy.x,
    s.proxy.y, s.proxy.z, s.force.x, s.force.y, s.force.z, s.contacts, s.shape, s.flags,
    static_cast<unsigned long long>(s.modelVersion),
    static_cast<unsigned long long>(s.droppedSamples));
  return row;
}

ServerConnection connection(const RemoteOptions& options)
{
  ServerConnection out;
  out.server = options.server;
  out.token = options.tokenFile.empty() ? "" : readTokenFile(options.tokenFile);
  out.tlsRootCertificates =
    options.tlsRoots.empty() ? "" : readPemFile(options.tlsRoots, "certificate");
  return out;
}

// Streams the server's state for --follow seconds into `summary` (samples, dropped, latency,
// touches) and, with --state-out, the CSV. A server that goes away is an error at once, not after
// the rest of --follow.
void followState(HapticClient& client, const RemoteOptions& options,
                 nlohmann::ordered_json& summary)
{
  std::mutex mutex;
  std::ostringstream rows;
  rows << "tick,t,finger_x,finger_y,finger_z,proxy_x,proxy_y,proxy_z,force_x,force_y,force_z,"
          "contacts,shape,flags,model_version,dropped_samples\n";
  std::size_t samples = 0;
  std::vector<double> latencies;
  nlohmann::ordered_json touches = nlohmann::ordered_json::array();
  std::uint64_t dropped = 0;
  if (options.follow > 0.0)
  {
    client.startStateStream(
      options.sampleRate,
      [&](const LiveSample& sample) {
        const std::lock_guard<std::mutex> lock(mutex);
        rows << stateRow(sample);
        ++samples;
        latencies.push_back(
          static_cast<double>(sample.receivedNanoseconds - sample.sentNanoseconds) / 1e6);
        dropped = sample.droppedSamples;
      },
      [&](const TouchChange& touch) {
        const std::lock_guard<std::mutex> lock(mutex);
        touches.push_back({{"t", touch.time}, {"shape", touch.shape}, {"touched", touch.touched}});
      });
    const auto end =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(options.follow);
    while (std::chrono::steady_clock::now() < end && client.stateStreamEnd().empty())
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const std::string ended = client.stopStateStream();
    if (!ended.empty())
    {
      throw InputError("--server", "the server at " + options.server + ": " + ended);
    }
  }
  if (!options.stateOut.empty())
  {
    writeFileAtomically(options.stateOut, rows.str());
  }
  summary["samples"] = samples;
  summary["dropped_samples"] = dropped;
  // Server's write to this client's read (the two wall clocks: meaningful on one machine).
  if (!latencies.empty())
  {
    std::sort(latencies.begin(), latencies.end());
    const auto at = [&latencies](double q) {
      return latencies[static_cast<std::size_t>(q * static_cast<double>(latencies.size() - 1))];
    };
    summary["latency_ms"] = {{"median", at(0.5)}, {"p99", at(0.99)}, {"max", latencies.back()}};
  }
  summary["touches"] = touches;
}

void requireFollowForStateOut(const RemoteOptions& options)
{
  if (!options.stateOut.empty() && !(options.follow > 0.0))
  {
    throw InputError("--state-out",
                     "needs --follow SECONDS: the state is streamed while following");
  }
}

int upload(const RemoteOptions& options)
{
  requireFollowForStateOut(options);
  if (options.meshes.empty() && options.uploadScene.empty())
  {
    throw InputError("--mesh", "upload needs the model: give --mesh FILE or --scene FILE");
  }
  HapticClient client(connection(options));
  if (!options.uploadScene.empty())
  {
    client.scene(options.uploadScene);
  }
  for (const std::string& mesh : options.meshes)
  {
    client.mesh(mesh, options.scale);
  }
  const ModelReceiptInfo receipt = client.commit();
  nlohmann::ordered_json summary;
  summary["server"] = options.server;
  summary["model_version"] = receipt.version;
  summary["shapes"] = receipt.shapes;
  summary["triangles"] = receipt.triangles;
  summary["build_ms"] = receipt.buildMilliseconds;
  summary["live_ms"] = receipt.liveMilliseconds;
  followState(client, options, summary);
  writeStandardOutput(summary.dump(2) + "\n");
  return kExitOk;
}

// An observer: follows the state while another client (or none) owns the model.
int follow(const RemoteOptions& options)
{
  requireFollowForStateOut(options);
  HapticClient client(connection(options), HapticClientRole::Observer);
  nlohmann::ordered_json summary;
  summary["server"] = options.server;
  followState(client, options, summary);
  writeStandardOutput(summary.dump(2) + "\n");
  return kExitOk;
}

int runRemote(const RemoteOptions& options)
{
  const SceneOptions& settings = options.scene;
  // Before anything is sent or written: a run never replaces what it reads.
  refuseOverlappingFiles(
    {{options.out, "--out"}, {options.bodiesOut, "--bodies-out"}, {options.summary, "--summary"}},
    {{settings.mesh, "--mesh"},
     {settings.scene, "--scene"},
     {settings.path, "--path"},
     {settings.texture, "--texture"},
     {options.tokenFile, "--token-file"}});
  RemoteRunRequest request;
  request.settings = settings;
  request.maxTicks = options.maxTicks;
  request.traceName = options.out;
  const ServerConnection server = connection(options);
  TraceWriter trace(options.out);
  // The bodies' poses come back from the server beside the ticks, written here as a local run
  // writes them.
  std::unique_ptr<BodyPoseWriter> poses;
  std::function<void(const BodyPoseRow&)> onBodyPose;
  if (!options.bodiesOut.empty())
  {
    poses = std::make_unique<BodyPoseWriter>(options.bodiesOut);
    onBodyPose = [&poses](const BodyPoseRow& row) {
      poses->write(row.tick, row.time, row.object, row.position, row.orientation,
                   &row.jointPosition);
    };
  }
  const std::string summary = runRemotely(
    server, request, [&trace](const HapticState& state) { trace.write(state); }, onBodyPose);
  // As a local run: the trace and the poses are put in place last, once the summary is written.
  trace.finish();
  if (poses != nullptr)
  {
    poses->finish();
  }
  if (!options.summary.empty())
  {
    writeFileAtomically(options.summary, summary);
  }
  trace.close();
  if (poses != nullptr)
  {
    poses->close();
  }
  writeStandardOutput(summary);
  return kExitOk;
}
} // namespace

Command addRemoteCommand(CLI::App& parent)
{
  auto options = std::make_shared<RemoteOptions>();
  CLI::App* app = parent.add_subcommand(kRemoteSummary.name, kRemoteSummary.description);
  app->add_option("--server", options->server, "HOST:PORT of a proxima serve")->required();
  app->add_option("--token-file", options->tokenFile,
                  "File whose first line is the server's token");
  app->add_option("--tls-ca", options->tlsRoots,
                  "PEM certificates that sign the server's (proxima serve --tls-cert): connect "
                  "over TLS");
  app->require_subcommand(1);
  CLI::App* run = app->add_subcommand(
    "run", "Play a finger path through a mesh or a scene on the server, as proxima run does here");
  addSceneOptionsThroughPath(*run, options->scene);
  run->add_option("--out", options->out, "Trace CSV to write here (trace v2)")->required();
  run->add_option("--summary", options->summary, "Also write the summary JSON to this file");
  run->add_option("--bodies-out", options->bodiesOut,
                  "With a scene that has bodies: write their poses here, as proxima run does "
                  "(tick,t,object,x,y,z,qw,qx,qy,qz,q; Documentation/Dynamics.md)");
  addSceneOptionsAfterPath(*run, options->scene);
  run->add_option("--max-ticks", options->maxTicks, "The most ticks the run may take (default 1e7)")
    ->check(tickCount());
  addTickBudgetOption(*run, options->scene,
                      "Default: none, so that the trace is reproducible bit for bit");
  run->callback([options, run] { checkSceneOptions(options->scene, *run); });
  CLI::App* uploadApp = app->add_subcommand(
    "upload",
    "Make meshes or a scene file the model of a proxima serve --device, and follow its state");
  CLI::Option* meshOption =
    uploadApp
      ->add_option("--mesh", options->meshes, "Mesh file, read here (repeat for more shapes)")
      ->check(CLI::ExistingFile);
  CLI::Option* sceneOption =
    uploadApp
      ->add_option("--scene", options->uploadScene,
                   "Scene file (with its meshes, textures and bodies), read here")
      ->excludes(meshOption);
  uploadApp->add_option("--scale", options->scale, "File units to metres (default 1)")
    ->check(numberIn(kMeshScaleRange))
    ->excludes(sceneOption);
  uploadApp
    ->add_option("--follow", options->follow,
                 "Seconds to stream the server's state after the model is live")
    ->check(numberIn(ParameterRange{0.0, false, 86400.0, " s"}));
  uploadApp->add_option("--rate", options->sampleRate, "State samples per second (1 to 1000)")
    ->check(numberIn(ParameterRange{1.0, false, 1000.0, " Hz"}));
  uploadApp->add_option("--state-out", options->stateOut, "The streamed state as CSV");
  CLI::App* followApp = app->add_subcommand(
    "follow", "Follow the state of a proxima serve --device as an observer (another client may "
              "own its model)");
  followApp->add_option("--follow", options->follow, "Seconds to stream the server's state")
    ->required()
    ->check(numberIn(ParameterRange{0.0, true, 86400.0, " s"}));
  followApp->add_option("--rate", options->sampleRate, "State samples per second (1 to 1000)")
    ->check(numberIn(ParameterRange{1.0, false, 1000.0, " Hz"}));
  followApp->add_option("--state-out", options->stateOut, "The streamed state as CSV");
  return Command{app, [options, uploadApp, followApp] {
                   if (uploadApp->parsed())
                   {
                     return upload(*options);
                   }
                   return followApp->parsed() ? follow(*options) : runRemote(*options);
                 }};
}

} // namespace proxima::cli
