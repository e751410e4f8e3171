// `proxima remote --server HOST:PORT run ...`: `proxima run`'s options, played by a
// `proxima serve` elsewhere (Documentation/Server.md). The mesh, path and texture files are sent
// whole; the server plays the path in lockstep and streams the ticks back, which are written here
// as a local run writes them: the same trace, bit for bit but for solve_ns.
#include "Command.h"
#include "SceneOptions.h"
#include "TokenFile.h"
#include "Validators.h"

#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/TraceWriter.h"
#include "Net/RemoteRuns.h"

#include <memory>

namespace proxima::cli
{
namespace
{
struct RemoteOptions
{
  std::string server;
  std::string tokenFile;
  SceneOptions scene;
  std::string out;
  std::string summary;
  double maxTicks = kDefaultMaxTicks;
};

int runRemote(const RemoteOptions& options)
{
  const SceneOptions& settings = options.scene;
  // Before anything is sent or written: a run never replaces what it reads.
  refuseOverlappingFiles({{options.out, "--out"}, {options.summary, "--summary"}},
                         {{settings.mesh, "--mesh"},
                          {settings.path, "--path"},
                          {settings.texture, "--texture"},
                          {options.tokenFile, "--token-file"}});
  RemoteRunRequest request;
  request.settings = settings;
  request.maxTicks = options.maxTicks;
  request.traceName = options.out;
  const std::string token = options.tokenFile.empty() ? "" : readTokenFile(options.tokenFile);
  TraceWriter trace(options.out);
  const std::string summary = runRemotely(
    options.server, token, request, [&trace](const HapticState& state) { trace.write(state); });
  trace.finish();
  if (!options.summary.empty())
  {
    writeFileAtomically(options.summary, summary);
  }
  trace.close();
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
  app->require_subcommand(1);
  CLI::App* run = app->add_subcommand(
    "run", "Play a finger path through a mesh on the server, as proxima run does here");
  addSceneOptionsThroughPath(*run, options->scene);
  run->add_option("--out", options->out, "Trace CSV to write here (trace v2)")->required();
  run->add_option("--summary", options->summary, "Also write the summary JSON to this file");
  addSceneOptionsAfterPath(*run, options->scene);
  run->add_option("--max-ticks", options->maxTicks, "The most ticks the run may take (default 1e7)")
    ->check(tickCount());
  addTickBudgetOption(*run, options->scene,
                      "Default: none, so that the trace is reproducible bit for bit");
  run->callback([options, run] { checkSceneOptions(options->scene, *run); });
  return Command{app, [options] { return runRemote(*options); }};
}

} // namespace proxima::cli
