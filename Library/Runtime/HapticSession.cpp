#include "Runtime/HapticSession.h"

#include "Runtime/HapticDevice.h"
#include "Runtime/HapticStep.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/SimulatedDevice.h"

#include <stdexcept>
#include <utility>

namespace proxima
{
namespace
{
// The device of one `step`: the finger it was given, and the force written back.
class GivenFinger final : public HapticDevice
{
public:
  explicit GivenFinger(const Vec3& finger)
    : m_finger(finger)
  {}
  DeviceSample read(double /*time*/) override { return DeviceSample{m_finger, true}; }
  void writeForce(const Vec3& /*force*/, double /*time*/) override {}
  const char* name() const override { return "session"; }

private:
  Vec3 m_finger;
};

// The solver's parameters from the session's: the spring and the time step are the servo's.
ProxyParameters solverParameters(const HapticSessionSettings& settings)
{
  if (!(settings.rate > 0.0))
  {
    throw std::invalid_argument("HapticSession: the servo rate must be positive");
  }
  ProxyParameters parameters = settings.proxy;
  parameters.stiffness = settings.servo.stiffness;
  parameters.timeStep = 1.0 / settings.rate;
  return parameters;
}
} // namespace

HapticSession::HapticSession(std::shared_ptr<const CollisionScene> scene,
                             const HapticSessionSettings& settings)
  : m_scene(std::move(scene))
  , m_settings(settings)
  , m_solver(std::make_unique<ProxySolver>())
  , m_servo(std::make_unique<ServoForce>(settings.servo))
{
  if (!m_scene)
  {
    throw std::invalid_argument("HapticSession: no scene");
  }
  m_settings.proxy = solverParameters(settings);
  m_solver->setScene(m_scene.get(), m_settings.proxy);
}

HapticSession::~HapticSession() = default;

const ProxyStartPlacement& HapticSession::placeProxy(const Vec3& finger)
{
  m_placement = placeProxyStart(*m_scene, m_settings.proxy, finger);
  resetProxyTo(*m_solver, m_placement);
  m_servo = std::make_unique<ServoForce>(m_settings.servo);
  m_tick = 0;
  m_placed = true;
  return m_placement;
}

void HapticSession::setDynamics(std::shared_ptr<TickDynamics> dynamics)
{
  m_dynamics = std::move(dynamics);
  if (m_dynamics != nullptr)
  {
    m_dynamics->attach(*m_solver);
  }
}

HapticState HapticSession::step(const Vec3& finger)
{
  if (!m_placed)
  {
    placeProxy(finger);
  }
  GivenFinger device(finger);
  const double time = static_cast<double>(m_tick) / m_settings.rate;
  HapticState state = hapticStep(m_tick, time, *m_solver, device, *m_servo, 0, m_dynamics.get());
  ++m_tick;
  return state;
}

std::vector<HapticState> HapticSession::run(const FingerPath& path)
{
  if (path.empty())
  {
    throw std::invalid_argument("HapticSession::run: the path has no samples");
  }
  placeProxy(path.positions.front());
  LockstepSettings lockstep;
  lockstep.rate = m_settings.rate;
  lockstep.startTime = path.startTime();
  lockstep.numTicks = ticksCovering(path.startTime(), path.endTime(), m_settings.rate);
  SimulatedDevice device(path);
  std::vector<HapticState> states;
  states.reserve(lockstep.numTicks);
  runLockstep(
    lockstep, *m_solver, device, m_settings.servo,
    [&](const HapticState& state) { states.push_back(state); }, m_dynamics.get());
  m_tick = lockstep.numTicks;
  return states;
}

} // namespace proxima
