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
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include <pthread.h>
#include <signal.h>

namespace proxima::cli
{
namespace
{
struct RemoteOptions
{
  std::string server;
  std::string tokenFile;
  std::string tlsRoots;
  // Seconds a client waits for a server that went away to come back (ReconnectPolicy::maxWait).
  double reconnect = 10.0;
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
  out.reconnect.maxWait = std::chrono::milliseconds(std::llround(options.reconnect * 1000.0));
  return out;
}

// SIGINT and SIGTERM end a --follow early, as its end would (the state and the summary are
// written): blocked before gRPC starts its threads, which inherit the mask (as proxima serve
// does), and waited for by a thread of this command's, which interrupts the client's wait.
class StopSignals
{
public:
  StopSignals()
  {
    sigemptyset(&m_signals);
    sigaddset(&m_signals, SIGINT);
    sigaddset(&m_signals, SIGTERM);
    // The command's own signal to the waiting thread that it is done.
    sigaddset(&m_signals, SIGUSR1);
    pthread_sigmask(SIG_BLOCK, &m_signals, nullptr);
  }
  ~StopSignals() { stopWatching(); }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  /// Until stopWatching, a stop signal interrupts `client`'s waitForEnd.
  void watch(HapticClient& client)
  {
    m_thread = std::thread([this, &client] {
      int signal = 0;
      sigwait(&m_signals, &signal);
      if (signal != SIGUSR1)
      {
        client.interruptWait();
      }
    });
  }
  void stopWatching()
  {
    if (m_thread.joinable())
    {
      pthread_kill(m_thread.native_handle(), SIGUSR1);
      m_thread.join();
    }
  }

private:
  sigset_t m_signals;
  std::thread m_thread;
};

// Streams the server's state for --follow seconds into `summary` (samples, dropped, latency,
// touches, reconnections) and, with --state-out, the CSV. A server that goes away is waited for
// (--reconnect) and followed again when it answers; one that does not come back is an error as
// soon as the client gives up, not after the rest of --follow. An owner whose ownership ends (its
// server went away: a restarted server starts without the uploaded model) is told so at once.
void followState(HapticClient& client, const RemoteOptions& options,
                 nlohmann::ordered_json& summary, StopSignals* stopSignals)
{
  std::mutex mutex;
  std::ostringstream rows;
  rows << "tick,t,finger_x,finger_y,finger_z,proxy_x,proxy_y,proxy_z,force_x,force_y,force_z,"
          "contacts,shape,flags,model_version,dropped_samples\n";
  std::size_t samples = 0;
  std::vector<double> latencies;
  nlohmann::ordered_json touches = nlohmann::ordered_json::array();
  std::uint64_t dropped = 0;
  std::uint32_t reconnections = 0;
  std::int64_t lastReceived = 0;
  if (options.follow > 0.0)
  {
    client.startStateStream(
      options.sampleRate,
      [&](const LiveSample& sample) {
        const std::lock_guard<std::mutex> lock(mutex);
        // Said on standard error as it happens: a script may wait for these lines.
        if (samples == 0)
        {
          std::cerr << "proxima remote: following the server at " << options.server << "\n";
        }
        if (sample.reconnections != reconnections)
        {
          reconnections = sample.reconnections;
          char gap[32];
          std::snprintf(gap, sizeof gap, "%.3f",
                        static_cast<double>(sample.receivedNanoseconds - lastReceived) / 1e9);
          std::cerr << "proxima remote: the server at " << options.server
                    << " answers again; following on (reconnection " << reconnections << ", " << gap
                    << " s without samples)\n";
        }
        lastReceived = sample.receivedNanoseconds;
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
    const auto end = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                       std::chrono::duration<double>(options.follow));
    if (stopSignals != nullptr)
    {
      stopSignals->watch(client);
    }
    client.waitForEnd(end);
    if (stopSignals != nullptr)
    {
      stopSignals->stopWatching();
    }
    const std::string ended = client.stopStateStream();
    // An upload's model is gone with its ownership (a restarted server starts without it): said
    // at once, whether or not the stream has come back.
    if (client.role() == HapticClientRole::Owner && !client.ownsModel())
    {
      throw OwnershipEnded("--server",
                           "the server at " + options.server +
                             ": this client no longer owns the model: " + client.ownershipEnd());
    }
    if (!ended.empty())
    {
      throw InputError("--server", ended.rfind("the server at ", 0) == 0
                                     ? ended
                                     : "the server at " + options.server + ": " + ended);
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
  summary["reconnections"] = client.stateStreamReconnections();
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
  // Only a --follow ends on SIGINT with its summary; an upload alone ends as any command does.
  std::unique_ptr<StopSignals> stopSignals =
    options.follow > 0.0 ? std::make_unique<StopSignals>() : nullptr;
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
  followState(client, options, summary, stopSignals.get());
  writeStandardOutput(summary.dump(2) + "\n");
  return kExitOk;
}

// An observer: follows the state while another client (or none) owns the model.
int follow(const RemoteOptions& options)
{
  requireFollowForStateOut(options);
  auto stopSignals = std::make_unique<StopSignals>();
  HapticClient client(connection(options), HapticClientRole::Observer);
  nlohmann::ordered_json summary;
  summary["server"] = options.server;
  followState(client, options, summary, stopSignals.get());
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
  auto trace = std::make_unique<TraceWriter>(options.out);
  // The bodies' poses come back from the server beside the ticks, written here as a local run
  // writes them.
  std::unique_ptr<BodyPoseWriter> poses;
  const auto startPoses = [&] {
    if (!options.bodiesOut.empty())
    {
      poses = std::make_unique<BodyPoseWriter>(options.bodiesOut);
    }
  };
  startPoses();
  std::function<void(const BodyPoseRow&)> onBodyPose;
  if (poses != nullptr)
  {
    onBodyPose = [&poses](const BodyPoseRow& row) {
      poses->write(row.tick, row.time, row.object, row.position, row.orientation,
                   &row.jointPosition);
    };
  }
  // A server that went away mid-run and came back plays the run again from its start: the rows
  // written so far go (each writer's temporary file is removed), and the run says so.
  const auto restart = [&] {
    std::cerr << "proxima remote: the server at " << options.server
              << " went away mid-run and answers again: playing the run again from its start\n";
    trace.reset();
    trace = std::make_unique<TraceWriter>(options.out);
    poses.reset();
    startPoses();
  };
  const std::string summary = runRemotely(
    server, request, [&trace](const HapticState& state) { trace->write(state); }, onBodyPose,
    restart);
  // As a local run: the trace and the poses are put in place last, once the summary is written.
  trace->finish();
  if (poses != nullptr)
  {
    poses->finish();
  }
  if (!options.summary.empty())
  {
    writeFileAtomically(options.summary, summary);
  }
  trace->close();
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
  app
    ->add_option("--reconnect", options->reconnect,
                 "Seconds to wait for a server that went away (a restart) to answer again before "
                 "giving up (default 10; 0: fail at once). Meanwhile calls are made again as gRPC "
                 "reconnects, 50 ms after the failure and then at intervals growing to 2 s; a "
                 "run is played again from its start, a follower follows on, and an owner is "
                 "told that it no longer owns the model")
    ->check(numberIn(ParameterRange{0.0, false, 3600.0, " s"}));
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
                 "Seconds to stream the server's state after the model is live (SIGINT or "
                 "SIGTERM ends it early, with the summary)")
    ->check(numberIn(ParameterRange{0.0, false, 86400.0, " s"}));
  uploadApp->add_option("--rate", options->sampleRate, "State samples per second (1 to 1000)")
    ->check(numberIn(ParameterRange{1.0, false, 1000.0, " Hz"}));
  uploadApp->add_option("--state-out", options->stateOut, "The streamed state as CSV");
  CLI::App* followApp = app->add_subcommand(
    "follow", "Follow the state of a proxima serve --device as an observer (another client may "
              "own its model)");
  followApp
    ->add_option("--follow", options->follow,
                 "Seconds to stream the server's state (SIGINT or SIGTERM ends it early, with the "
                 "summary)")
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
