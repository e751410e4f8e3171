// vtkHapticRenderer: the bridge between the pipeline and the haptic threads. It owns the
// threaded runtime (Runtime/ThreadedRuntime.h): Start and Stop run its servo and proxy loops,
// UpdateScene brings the vtkHapticScene up to date and publishes a new snapshot when the scene
// made one (the haptic threads swap to it once it is complete and never wait for it), and
// GetState hands the render thread the latest proxy, finger, force and contacts through the
// runtime's lock-free hand-off. Call everything from one (the render) thread.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticDevice.h"
#include "Runtime/HapticState.h"
#include "Runtime/LoopStatistics.h"
#include "Runtime/TickBudget.h"
#include "Runtime/TickDynamics.h"

#include <vtkObject.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkHapticScene;

namespace proxima
{
class SimulatedDevice;
class ThreadedRuntime;
} // namespace proxima

/// The bridge between a VTK pipeline and the haptic threads: owns the threaded runtime, runs its
/// servo and proxy loops, publishes the scene to them and hands the latest state back. Call
/// everything from one thread (the render thread).
class vtkHapticRenderer : public vtkObject
{
public:
  /// A new renderer, with no scene or device and no runtime until Start.
  static vtkHapticRenderer* New();
  /// Prints the properties, whether the loops run, and the published and live scene versions.
  vtkTypeMacro(vtkHapticRenderer, vtkObject) void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene to render (default none). UpdateScene updates it and publishes its snapshots.
  void SetScene(vtkHapticScene* scene);
  /// The scene set with SetScene, or null (no new reference).
  vtkGetObjectMacro(Scene, vtkHapticScene);
  ///@}

  /// Or a snapshot built elsewhere (a scene file): published at Start, or at once when running.
  /// Used when no vtkHapticScene is set.
  void SetCollisionScene(std::shared_ptr<const proxima::CollisionScene> scene);
  /// The same with the scene's bodies (paper section 6; Dynamics/BodyCoupling.h, made by
  /// IO/Scene/SceneBodies.h from a scene file), published with it: each proxy update pushes and
  /// steps them on the proxy thread. They are not reset at a restart: a looped path finds them
  /// where it left them. GetBodyPoses hands their poses to the render thread.
  void SetCollisionScene(std::shared_ptr<const proxima::CollisionScene> scene,
                         std::shared_ptr<proxima::TickDynamics> bodies);
  /// Where the bodies are after the newest proxy update (count 0 without bodies or before Start).
  proxima::BodyPoses GetBodyPoses() const;
  /// The newest scene snapshot (published, or waiting for Start); null before any. For the
  /// thread that sets scenes, as the snapshot is replaced there.
  std::shared_ptr<const proxima::CollisionScene> GetCollisionScene() const { return m_current; }
  /// The scene objects that deform (a scene's tissues, given with SetCollisionScene); none
  /// without.
  std::vector<std::uint32_t> GetDeformingObjects() const
  {
    return m_bodies != nullptr ? m_bodies->deformingObjects() : std::vector<std::uint32_t>{};
  }

  /// The device (not owned; must outlive the run), or a finger path played by a simulated device
  /// the renderer owns. Set one before Start, or between Stop and the next Start (a device
  /// change: the next Start builds a new runtime on it).
  void SetDevice(proxima::HapticDevice* device);
  /// A finger path, played by a simulated device the renderer owns, in place of a device. An
  /// error, and no change, while the loops run or for an empty path.
  void SetFingerPath(const proxima::FingerPath& path);
  /// The same, a sample at a time (time in seconds, never going back; position in metres): the
  /// way in from VTK's Python, where FingerPath is not wrapped.
  void AddFingerSample(double time, double x, double y, double z);

  ///@{
  /// Proxy radius in metres (default 0.001). Read at Start and at each published scene.
  vtkSetClampMacro(ProxyRadius, double, 1e-9, VTK_DOUBLE_MAX);
  /// Proxy radius (m).
  vtkGetMacro(ProxyRadius, double);
  /// Spring stiffness kp in N/m (default 1000): the servo's, read at Start, and the one the proxy
  /// update's viscous friction uses, read at each published scene.
  vtkSetClampMacro(Stiffness, double, 1e-9, VTK_DOUBLE_MAX);
  /// Spring stiffness kp (N/m).
  vtkGetMacro(Stiffness, double);
  /// Force clamp in N (default 10). Read at Start.
  vtkSetClampMacro(MaxForce, double, 1e-9, VTK_DOUBLE_MAX);
  /// Force clamp (N).
  vtkGetMacro(MaxForce, double);
  /// Move/update iterations allowed in one proxy update (default 256, 1 to 1000). Read at Start
  /// and at each published scene.
  vtkSetClampMacro(MaxIterations, int, 1, 1000);
  /// Move/update iterations allowed in one proxy update.
  vtkGetMacro(MaxIterations, int);
  ///@}

  ///@{
  /// Contact skin in metres (ProxyParameters::skin; default 0: from the scene, see
  /// Documentation/Epsilons.md).
  vtkSetClampMacro(Skin, double, 0.0, VTK_DOUBLE_MAX);
  /// Contact skin (m; 0: from the scene).
  vtkGetMacro(Skin, double);
  ///@}

  ///@{
  /// The proxy loop's work budget per tick (RuntimeSettings::tickBudget): seconds of wall time
  /// (default 0: none), move/update iterations (default proxima::kDefaultTickBudgetIterations,
  /// the real-time default, deterministic) and a wall-time safety cap used when no seconds are
  /// given (default proxima::kTickSafetyCapSeconds, 200e-6: within a 4 kHz servo's 250 us
  /// period). All 0 means no budget. A budget-limited tick leaves the proxy feasible where it
  /// stopped; the next tick goes on from there. Read at Start.
  vtkSetClampMacro(TickBudgetSeconds, double, 0.0, 1.0);
  /// The budget's wall time per tick (s; 0: none).
  vtkGetMacro(TickBudgetSeconds, double);
  /// The budget's move/update iterations per tick (0: none). Read at Start.
  vtkSetClampMacro(TickBudgetIterations, int, 0, 1000000);
  /// The budget's move/update iterations per tick (0: none).
  vtkGetMacro(TickBudgetIterations, int);
  /// The wall-time safety cap per tick (s; 0: none), used when TickBudgetSeconds is 0. Read at
  /// Start.
  vtkSetClampMacro(TickSafetyCapSeconds, double, 0.0, 1.0);
  /// The wall-time safety cap per tick (s; 0: none).
  vtkGetMacro(TickSafetyCapSeconds, double);
  ///@}

  ///@{
  /// Servo rate in Hz (default 4000), from 1000 to 10000 (Runtime/ServoRate.h, the runtime's one
  /// rule). Unlike VTK's clamped properties, a rate outside is refused: SetServoRate reports an
  /// error, keeps the rate it had and returns false, so that the loops and the proxy's time step
  /// (derived from the rate at each published scene) never disagree.
  bool SetServoRate(double rate);
  /// Servo rate (Hz).
  vtkGetMacro(ServoRate, double);
  ///@}

  ///@{
  /// Proxy-update rate in Hz (default 0: the servo's).
  vtkSetClampMacro(ProxyRate, double, 0.0, 10000.0);
  /// Proxy-update rate (Hz; 0: the servo's).
  vtkGetMacro(ProxyRate, double);
  ///@}

  ///@{
  /// Ask for real-time (SCHED_FIFO) threads (default off: a desktop viewer rarely has the
  /// privilege; Start's message says whether it was granted).
  vtkSetMacro(RealtimeScheduling, vtkTypeBool);
  /// Whether real-time threads are asked for.
  vtkGetMacro(RealtimeScheduling, vtkTypeBool);
  /// Asks for real-time threads. Read at Start.
  vtkBooleanMacro(RealtimeScheduling, vtkTypeBool);
  /// \fn void vtkHapticRenderer::RealtimeSchedulingOff()
  /// Asks for threads of normal priority. Read at Start.
  ///@}

  ///@{
  /// The run ends by itself after this many seconds of servo clock (default 0: at Stop).
  vtkSetClampMacro(Duration, double, 0.0, VTK_DOUBLE_MAX);
  /// The run's length on the servo clock (s; 0: until Stop).
  vtkGetMacro(Duration, double);
  ///@}

  ///@{
  /// Stream every servo tick's state to the render thread (RuntimeSettings::streamCapacity):
  /// DrainStates hands over those published since its last call, for a live scorer that must
  /// see every tick rather than the latest at each frame. Default 0: no stream.
  vtkSetClampMacro(StateStreamCapacity, vtkIdType, 0, 10000000);
  /// States the stream holds for DrainStates (0: no stream).
  vtkGetMacro(StateStreamCapacity, vtkIdType);
  ///@}

  /// Where the proxy starts (in free space). Default: the device's first sample.
  void SetProxyStart(double x, double y, double z);

  /// Builds the runtime, publishes the scene and starts both loops; after Stop or a finished run,
  /// starts a new run from the proxy start on the newest scene. False if there is no
  /// scene or device, or the threads did not start; GetStartMessage says why (and whether
  /// real-time scheduling was granted).
  bool Start();
  /// Stops both loops and waits for them; the runtime stays (its state, statistics and streamed
  /// states can still be read) until the next Start. Nothing when not running.
  void Stop();
  /// True while the loops run: after a successful Start, until Stop or the end of Duration.
  bool IsRunning() const;
  /// The run reached Duration.
  bool IsFinished() const;
  /// Why the last Start failed, or the runtime's message on a successful one (whether real-time
  /// scheduling was granted).
  const std::string& GetStartMessage() const { return m_startMessage; }

  /// Updates the vtkHapticScene and, if it made a new snapshot, publishes it (or keeps it for
  /// Start). Returns the runtime's version of the newest published scene (0 before any).
  vtkTypeUInt64 UpdateScene();

  /// The latest state of the haptic threads (a default state before Start).
  proxima::HapticState GetState() const;
  ///@{
  /// Parts of the latest state, for VTK's Python, where HapticState is not wrapped: the proxy's
  /// and the finger's centres (metres), the force on the device (N), the active contacts, and the
  /// servo tick that produced it. Each call reads the latest state anew.
  void GetProxyPosition(double position[3]) const;
  /// The finger's centre in the latest state (m).
  void GetFingerPosition(double position[3]) const;
  /// The force on the device in the latest state (N).
  void GetForce(double force[3]) const;
  /// The active contacts in the latest state (0 to 3).
  int GetNumberOfContacts() const;
  /// The servo tick that produced the latest state.
  vtkTypeUInt64 GetStateTick() const;
  ///@}
  /// The runtime's version of the scene the proxy loop uses (0 before the first is live).
  vtkTypeUInt64 GetLiveSceneVersion() const;
  /// The servo loop's timing statistics (a default LoopStatistics before Start).
  proxima::LoopStatistics GetServoStatistics() const;
  /// Appends the ticks' states streamed since the last call (SetStateStreamCapacity) to `out`,
  /// in tick order; one reader thread. Returns how many.
  std::size_t DrainStates(std::vector<proxima::HapticState>& out);
  /// Streamed states dropped because DrainStates was called too seldom.
  vtkTypeUInt64 GetDroppedStates() const;
  /// The proxy loop's timing statistics (a default LoopStatistics before Start).
  proxima::LoopStatistics GetProxyStatistics() const;
  /// The runtime itself (null before Start), for what this class does not forward.
  proxima::ThreadedRuntime* GetRuntime() { return m_runtime.get(); }

protected:
  vtkHapticRenderer();
  ~vtkHapticRenderer() override;

  vtkHapticScene* Scene = nullptr;   ///< The scene (a reference held): SetScene.
  vtkIdType StateStreamCapacity = 0; ///< States streamed: SetStateStreamCapacity.
  double ProxyRadius = 0.001;        ///< Proxy radius (m): SetProxyRadius.
  double Stiffness = 1000.0;         ///< Spring stiffness kp (N/m): SetStiffness.
  double MaxForce = 10.0;            ///< Force clamp (N): SetMaxForce.
  int MaxIterations = 256;           ///< Iterations per proxy update: SetMaxIterations.
  double Skin = 0.0;                 ///< Contact skin (m; 0: from the scene): SetSkin.
  double TickBudgetSeconds = 0.0;    ///< Tick budget's wall time (s): SetTickBudgetSeconds.
  /// Tick budget's move/update iterations: SetTickBudgetIterations.
  int TickBudgetIterations = proxima::kDefaultTickBudgetIterations;
  /// Wall-time safety cap per tick (s): SetTickSafetyCapSeconds.
  double TickSafetyCapSeconds = proxima::kTickSafetyCapSeconds;
  double ServoRate = 4000.0;          ///< Servo rate (Hz): SetServoRate.
  double ProxyRate = 0.0;             ///< Proxy-update rate (Hz; 0: the servo's): SetProxyRate.
  vtkTypeBool RealtimeScheduling = 0; ///< Ask for real-time threads: SetRealtimeScheduling.
  double Duration = 0.0;              ///< Run length (s; 0: until Stop): SetDuration.

private:
  vtkHapticRenderer(const vtkHapticRenderer&) = delete;
  void operator=(const vtkHapticRenderer&) = delete;

  bool Publish(std::shared_ptr<const proxima::CollisionScene> scene);

  std::unique_ptr<proxima::SimulatedDevice> m_ownedDevice;
  /// The samples of AddFingerSample so far.
  proxima::FingerPath m_addedPath;
  proxima::HapticDevice* m_device = nullptr;
  std::unique_ptr<proxima::ThreadedRuntime> m_runtime;
  /// The newest snapshot (published, or waiting for Start).
  std::shared_ptr<const proxima::CollisionScene> m_current;
  /// The bodies of m_current when SetCollisionScene gave them.
  std::shared_ptr<proxima::TickDynamics> m_bodies;
  /// The rate of the running proxy loop (ProxyRate, or ServoRate when 0) as of Start: the time
  /// step of every scene published to this runtime.
  double m_proxyLoopRate = 4000.0;
  std::uint64_t m_sceneVersionSeen = 0;
  std::uint64_t m_publishedVersion = 0;
  bool m_proxyStartSet = false;
  proxima::Vec3 m_proxyStart;
  std::string m_startMessage;
};
