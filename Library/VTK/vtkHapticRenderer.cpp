#include "VTK/vtkHapticRenderer.h"

#include "Runtime/ServoRate.h"
#include "Runtime/SimulatedDevice.h"
#include "Runtime/ThreadedRuntime.h"
#include "VTK/vtkHapticScene.h"

#include <vtkObjectFactory.h>

#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkHapticRenderer);
vtkCxxSetObjectMacro(vtkHapticRenderer, Scene, vtkHapticScene);

vtkHapticRenderer::vtkHapticRenderer() = default;

vtkHapticRenderer::~vtkHapticRenderer()
{
  this->Stop();
  // The runtime goes before the device it reads.
  m_runtime.reset();
  this->SetScene(nullptr);
}

void vtkHapticRenderer::SetCollisionScene(std::shared_ptr<const proxima::CollisionScene> scene)
{
  this->SetCollisionScene(std::move(scene), nullptr);
}

proxima::BodyPoses vtkHapticRenderer::GetBodyPoses() const
{
  return m_runtime ? m_runtime->latestBodyPoses() : proxima::BodyPoses{};
}

void vtkHapticRenderer::SetCollisionScene(std::shared_ptr<const proxima::CollisionScene> scene,
                                          std::shared_ptr<proxima::TickDynamics> bodies)
{
  m_current = scene;
  m_bodies = std::move(bodies);
  if (m_runtime)
  {
    this->Publish(std::move(scene));
  }
  this->Modified();
}

void vtkHapticRenderer::SetDevice(proxima::HapticDevice* device)
{
  // A stopped runtime no longer reads its device (the next Start builds a new one): a window's
  // device menu switches devices between Stop and Start.
  if (this->IsRunning())
  {
    vtkErrorMacro("The device cannot change while the loops run; Stop first.");
    return;
  }
  m_ownedDevice.reset();
  m_device = device;
  this->Modified();
}

void vtkHapticRenderer::SetFingerPath(const proxima::FingerPath& path)
{
  if (this->IsRunning())
  {
    vtkErrorMacro("The finger path cannot change while the loops run; Stop first.");
    return;
  }
  if (path.empty())
  {
    vtkErrorMacro("An empty finger path.");
    return;
  }
  m_ownedDevice = std::make_unique<proxima::SimulatedDevice>(path);
  m_device = m_ownedDevice.get();
  this->Modified();
}

void vtkHapticRenderer::AddFingerSample(double time, double x, double y, double z)
{
  if (!m_addedPath.empty() && !(time >= m_addedPath.endTime()))
  {
    vtkErrorMacro("AddFingerSample: time " << time << " s goes back before the last sample's "
                                           << m_addedPath.endTime() << " s.");
    return;
  }
  if (!std::isfinite(time) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
  {
    vtkErrorMacro("AddFingerSample: a sample that is not finite.");
    return;
  }
  m_addedPath.append(time, proxima::Vec3{x, y, z});
  this->SetFingerPath(m_addedPath);
}

bool vtkHapticRenderer::SetServoRate(double rate)
{
  const std::string error = proxima::servoRateError(rate);
  if (!error.empty())
  {
    vtkErrorMacro("SetServoRate refused: " << error << "; the rate stays " << this->ServoRate
                                           << " Hz.");
    return false;
  }
  if (this->ServoRate != rate)
  {
    this->ServoRate = rate;
    this->Modified();
  }
  return true;
}

void vtkHapticRenderer::SetProxyStart(double x, double y, double z)
{
  m_proxyStart = {x, y, z};
  m_proxyStartSet = true;
  this->Modified();
}

bool vtkHapticRenderer::Publish(std::shared_ptr<const proxima::CollisionScene> scene)
{
  if (!scene || !m_runtime)
  {
    return false;
  }
  proxima::ProxyParameters parameters;
  parameters.radius = this->ProxyRadius;
  parameters.maxIterations = this->MaxIterations;
  parameters.skin = this->Skin;
  parameters.stiffness = this->Stiffness;
  // The proxy loop's rate as the running runtime has it: ServoRate and ProxyRate may have been
  // set again since Start.
  parameters.timeStep = 1.0 / m_proxyLoopRate;
  m_publishedVersion =
    m_runtime->publishScene(std::move(scene), parameters, m_proxyStart, nullptr, m_bodies);
  return true;
}

bool vtkHapticRenderer::Start()
{
  if (this->IsRunning())
  {
    return true;
  }
  if (!m_device)
  {
    m_startMessage = "no device: SetDevice or SetFingerPath first";
    return false;
  }
  this->UpdateScene();
  if (!m_current)
  {
    m_startMessage = "no scene: SetScene (and a successful Update) or SetCollisionScene first";
    return false;
  }
  if (!m_proxyStartSet)
  {
    // Read before the servo thread exists, so the device has one reader at a time.
    m_proxyStart = m_device->read(0.0).position;
  }
  proxima::ServoParameters servo;
  servo.stiffness = this->Stiffness;
  servo.maxForce = this->MaxForce;
  proxima::RuntimeSettings settings;
  settings.servoRate = this->ServoRate;
  settings.proxyRate = this->ProxyRate;
  settings.realtimeScheduling = this->RealtimeScheduling != 0;
  settings.duration = this->Duration;
  settings.streamCapacity = static_cast<std::size_t>(this->StateStreamCapacity);
  settings.tickBudget = proxima::TickWorkBudget{this->TickBudgetSeconds, this->TickBudgetIterations,
                                                this->TickSafetyCapSeconds};
  m_proxyLoopRate = settings.proxyRate > 0.0 ? settings.proxyRate : settings.servoRate;
  m_runtime.reset();
  try
  {
    m_runtime = std::make_unique<proxima::ThreadedRuntime>(*m_device, servo, settings);
  }
  catch (const std::invalid_argument& error)
  {
    // SetServoRate keeps the rate valid; this is the runtime's own check, should that change.
    m_startMessage = error.what();
    return false;
  }
  // A restart publishes the newest snapshot again: a new runtime starts without a scene.
  this->Publish(m_current);
  return m_runtime->start(m_startMessage);
}

void vtkHapticRenderer::Stop()
{
  if (m_runtime)
  {
    m_runtime->stop();
  }
}

bool vtkHapticRenderer::IsRunning() const
{
  return m_runtime && m_runtime->running();
}

bool vtkHapticRenderer::IsFinished() const
{
  return m_runtime && m_runtime->finished();
}

vtkTypeUInt64 vtkHapticRenderer::UpdateScene()
{
  if (this->Scene)
  {
    this->Scene->Update();
    if (this->Scene->GetSceneVersion() != m_sceneVersionSeen && this->Scene->GetCollisionScene())
    {
      m_sceneVersionSeen = this->Scene->GetSceneVersion();
      m_current = this->Scene->GetCollisionScene();
      m_bodies = nullptr; // a pipeline's scene has no bodies
      if (m_runtime)
      {
        this->Publish(m_current);
      }
    }
  }
  return m_publishedVersion;
}

proxima::HapticState vtkHapticRenderer::GetState() const
{
  return m_runtime ? m_runtime->latestState() : proxima::HapticState{};
}

namespace
{
void copyTo(const proxima::Vec3& v, double out[3])
{
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
}
} // namespace

void vtkHapticRenderer::GetProxyPosition(double position[3]) const
{
  copyTo(this->GetState().proxy, position);
}

void vtkHapticRenderer::GetFingerPosition(double position[3]) const
{
  copyTo(this->GetState().finger, position);
}

void vtkHapticRenderer::GetForce(double force[3]) const
{
  copyTo(this->GetState().force, force);
}

int vtkHapticRenderer::GetNumberOfContacts() const
{
  return this->GetState().numContacts;
}

vtkTypeUInt64 vtkHapticRenderer::GetStateTick() const
{
  return this->GetState().tick;
}

vtkTypeUInt64 vtkHapticRenderer::GetLiveSceneVersion() const
{
  return m_runtime ? m_runtime->liveSceneVersion() : 0;
}

std::size_t vtkHapticRenderer::DrainStates(std::vector<proxima::HapticState>& out)
{
  return m_runtime ? m_runtime->drainStates(out) : 0;
}

vtkTypeUInt64 vtkHapticRenderer::GetDroppedStates() const
{
  return m_runtime ? m_runtime->droppedStates() : 0;
}

proxima::LoopStatistics vtkHapticRenderer::GetServoStatistics() const
{
  return m_runtime ? m_runtime->servoStatistics() : proxima::LoopStatistics{};
}

proxima::LoopStatistics vtkHapticRenderer::GetProxyStatistics() const
{
  return m_runtime ? m_runtime->proxyStatistics() : proxima::LoopStatistics{};
}

void vtkHapticRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scene: " << this->Scene << "\n";
  os << indent << "ProxyRadius: " << this->ProxyRadius << "\n";
  os << indent << "Stiffness: " << this->Stiffness << "\n";
  os << indent << "MaxForce: " << this->MaxForce << "\n";
  os << indent << "MaxIterations: " << this->MaxIterations << "\n";
  os << indent << "Skin: " << this->Skin << " (0: from the scene)\n";
  os << indent << "TickBudgetSeconds: " << this->TickBudgetSeconds
     << ", TickBudgetIterations: " << this->TickBudgetIterations
     << ", TickSafetyCapSeconds: " << this->TickSafetyCapSeconds << " (all 0: none)\n";
  os << indent << "StateStreamCapacity: " << this->StateStreamCapacity << "\n";
  os << indent << "ServoRate: " << this->ServoRate << "\n";
  os << indent << "ProxyRate: " << this->ProxyRate << "\n";
  os << indent << "RealtimeScheduling: " << (this->RealtimeScheduling ? "On" : "Off") << "\n";
  os << indent << "Duration: " << this->Duration << "\n";
  os << indent << "Running: " << (this->IsRunning() ? "yes" : "no") << ", published scene version "
     << m_publishedVersion << ", live " << this->GetLiveSceneVersion() << "\n";
}
