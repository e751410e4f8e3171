// `proxima serve`: the haptic server (Documentation/Server.md; paper section 7). Listens on
// --listen (loopback by default; any other address needs --token-file), plays clients' paths in
// lockstep and streams their ticks back; with --device it also owns the device and the threaded
// runtime, and clients upload models into it and follow the proxy (Net/HapticClient.h). Until
// SIGINT or SIGTERM.
#include "Command.h"
#include "DeviceChoice.h"
#include "LoopReport.h"
#include "PemFile.h"
#include "TokenFile.h"
#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "Net/RemoteRuns.h"
#include "Runtime/ServoRate.h"
#include "Runtime/ThreadedRuntime.h"

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
  std::string tlsCertificate;
  std::string tlsKey;
  double maxTicks = kDefaultMaxTicks;
  // The live server: its device, and the servo and proxy its clients' models are felt with.
  DeviceChoiceOptions device;
  std::string path;
  double rate = 1000.0;
  double radius = 0.001;
  double stiffness = 1000.0;
  double maxForce = 10.0;
  std::string summary;
};

// The device and its threads, running on an empty scene until a client uploads a model.
struct LiveRuntime
{
  std::unique_ptr<RunDevice> device;
  std::unique_ptr<ThreadedRuntime> runtime;
};

std::unique_ptr<LiveRuntime> startLiveRuntime(const ServeOptions& options, ProxyParameters& proxy)
{
  if (!isServoRate(options.rate))
  {
    throw InputError("--rate", servoRateError(options.rate));
  }
  FingerPath path;
  if (!options.path.empty())
  {
    path = readFingerPathFile(options.path);
  }
  else if (options.device.device == "sim")
  {
    throw InputError("--path", "--device sim plays a finger path: give --path");
  }
  else
  {
    path.append(0.0, Vec3{}); // the workspace centred on the origin
  }
  auto live = std::make_unique<LiveRuntime>();
  live->device = std::make_unique<RunDevice>(options.device, path, 0);
  ServoParameters servo;
  servo.stiffness = options.stiffness;
  servo.maxForce = options.maxForce;
  RuntimeSettings settings;
  settings.servoRate = options.rate;
  live->runtime = std::make_unique<ThreadedRuntime>(live->device->device(), servo, settings);
  proxy.radius = options.radius;
  live->runtime->publishScene(std::make_shared<CollisionScene>(), proxy, path.positions.front());
  std::string message;
  if (!live->runtime->start(message))
  {
    throw std::runtime_error(message);
  }
  if (message.find("refused") != std::string::npos)
  {
    std::fprintf(stderr, "proxima serve: %s\n", message.c_str());
  }
  return live;
}

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
  if (!options.tlsCertificate.empty())
  {
    settings.tlsCertificateChain = readPemFile(options.tlsCertificate, "certificate");
    settings.tlsPrivateKey = readPemFile(options.tlsKey, "private key");
  }
  std::unique_ptr<LiveRuntime> live;
  if (!options.device.device.empty())
  {
    live = startLiveRuntime(options, settings.liveProxy);
    settings.runtime = live->runtime.get();
    settings.liveStiffness = options.stiffness;
    settings.liveRate = options.rate;
  }
  RemoteRunServer server(settings);
  // The port a script asked for with :0 is on standard output, one line, at once.
  const std::string host = parseListenAddress(options.listen).host;
  std::printf("proxima serve: listening on %s:%d\n", host.c_str(), server.port());
  std::fflush(stdout);
  int signal = 0;
  sigwait(&stopSignals, &signal);
  server.shutdown();
  if (live)
  {
    live->runtime->stop();
    // How the loops kept their deadlines while clients came and went (Documentation/Server.md).
    const LoopStatistics servo = live->runtime->servoStatistics();
    std::fprintf(stderr, "proxima serve: servo %s\n", deadlineLine(servo).c_str());
    if (!options.summary.empty())
    {
      nlohmann::ordered_json summary;
      summary["device"] = options.device.device;
      summary["rate_hz"] = options.rate;
      summary["model_version"] = live->runtime->liveSceneVersion();
      summary["longest_model_install_us"] =
        static_cast<double>(live->runtime->longestSceneInstallNanoseconds()) / 1e3;
      summary["servo"] = loopJson(servo, live->runtime->servoScheduling());
      summary["proxy"] = loopJson(live->runtime->proxyStatistics());
      writeFileAtomically(options.summary, summary.dump(2) + "\n");
    }
  }
  return kExitOk;
}
} // namespace

Command addServeCommand(CLI::App& parent)
{
  auto options = std::make_shared<ServeOptions>();
  CLI::App* app = parent.add_subcommand(kServeSummary.name, kServeSummary.description);
  app->add_option("--listen", options->listen,
                  "HOST:PORT or [IPV6]:PORT to listen on (default 127.0.0.1:50051; a HOST "
                  "alone takes port 50051; port 0 takes a free one, printed on standard "
                  "output); an address other than loopback (127.0.0.0/8, localhost, [::1]) "
                  "needs --token-file");
  app->add_option("--token-file", options->tokenFile,
                  "File whose first line is the token every client must send");
  CLI::Option* certificate =
    app->add_option("--tls-cert", options->tlsCertificate,
                    "PEM certificate (chain) of this server: clients connect over TLS");
  CLI::Option* key = app->add_option("--tls-key", options->tlsKey, "PEM private key of --tls-cert");
  certificate->needs(key);
  key->needs(certificate);
  app
    ->add_option("--max-ticks", options->maxTicks,
                 "The most ticks one client's run may take (a run asking for more is refused)")
    ->check(tickCount())
    ->capture_default_str();
  // The live server (Documentation/Server.md, "The live server").
  addDeviceOptions(*app, options->device);
  options->device.device.clear(); // no device unless asked: remote runs only
  app->add_option("--path", options->path,
                  "With --device sim: the finger path it plays in real time (and holds at its "
                  "end); with another device: where its workspace centre goes (its first row)");
  app->add_option("--rate", options->rate, "With --device: the servo rate in Hz")
    ->capture_default_str();
  app->add_option("--radius", options->radius, "With --device: the proxy's radius in metres")
    ->check(numberIn(kProxyRadiusRange))
    ->capture_default_str();
  app->add_option("--stiffness", options->stiffness, "With --device: the servo's kp in N/m")
    ->check(numberIn(kStiffnessRange))
    ->capture_default_str();
  app->add_option("--max-force", options->maxForce, "With --device: the force clamp in N")
    ->check(numberIn(kMaxForceRange))
    ->capture_default_str();
  app->add_option("--summary", options->summary,
                  "With --device: when stopped, write the servo's and the proxy loop's "
                  "statistics to this JSON file");
  return Command{app, [options] { return serve(*options); }};
}

} // namespace proxima::cli
