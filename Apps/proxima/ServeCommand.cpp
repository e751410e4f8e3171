// `proxima serve`: the haptic server's side of remote runs (Documentation/Server.md). Listens on
// --listen (loopback by default; any other address needs --token-file), plays each client's path
// in lockstep and streams its ticks back, until SIGINT or SIGTERM.
#include "Command.h"
#include "TokenFile.h"
#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "Net/RemoteRuns.h"

#include <csignal>
#include <cstdio>
#include <memory>
#include <pthread.h>

namespace proxima::cli
{
namespace
{
struct ServeOptions
{
  std::string listen = "127.0.0.1:50051";
  std::string tokenFile;
  double maxTicks = kDefaultMaxTicks;
};

int serve(const ServeOptions& options)
{
  // The stop signals are waited for here, not handled asynchronously: blocked before gRPC starts
  // its threads, which inherit the mask.
  sigset_t stopSignals;
  sigemptyset(&stopSignals);
  sigaddset(&stopSignals, SIGINT);
  sigaddset(&stopSignals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);

  RemoteServerSettings settings;
  settings.listen = options.listen;
  settings.maxTicks = options.maxTicks;
  if (!options.tokenFile.empty())
  {
    settings.token = readTokenFile(options.tokenFile);
  }
  RemoteRunServer server(settings);
  // The port a script asked for with :0 is on standard output, one line, at once.
  const std::string host = options.listen.substr(0, options.listen.rfind(':'));
  std::printf("proxima serve: listening on %s:%d\n", host.c_str(), server.port());
  std::fflush(stdout);
  int signal = 0;
  sigwait(&stopSignals, &signal);
  server.shutdown();
  return kExitOk;
}
} // namespace

Command addServeCommand(CLI::App& parent)
{
  auto options = std::make_shared<ServeOptions>();
  CLI::App* app = parent.add_subcommand(kServeSummary.name, kServeSummary.description);
  app->add_option("--listen", options->listen,
                  "HOST:PORT to listen on (default 127.0.0.1:50051; port 0 takes a free one, "
                  "printed on standard output); an address other than loopback needs "
                  "--token-file");
  app->add_option("--token-file", options->tokenFile,
                  "File whose first line is the token every client must send");
  app
    ->add_option("--max-ticks", options->maxTicks,
                 "The most ticks one client's run may take (a run asking for more is refused)")
    ->check(tickCount())
    ->capture_default_str();
  return Command{app, [options] { return serve(*options); }};
}

} // namespace proxima::cli
