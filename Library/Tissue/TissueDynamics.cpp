#include "Tissue/TissueDynamics.h"

#include "Geometry/ClosestPoint.h"
#include "Runtime/DeadlineClock.h"
#include "Runtime/FutexWord.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace proxima
{

namespace
{
// Each tissue's points at rest: what the hand-over holds before the first step, and the room it
// keeps for every later one.
TissueDynamics::Surfaces surfacesAtRest(const std::vector<TissueObject>& tissues)
{
  TissueDynamics::Surfaces surfaces;
  for (const TissueObject& tissue : tissues)
  {
    surfaces.points.push_back(tissue.tets.points);
  }
  return surfaces;
}
} // namespace

TissueDynamics::TissueDynamics(std::vector<TissueObject> tissues, double stiffness, double rate)
  : m_surfaces(surfacesAtRest(tissues))
  , m_stiffness(stiffness)
{
  if (tissues.empty())
  {
    throw std::invalid_argument("TissueDynamics: no tissue");
  }
  if (!(stiffness > 0.0) || !(rate > 0.0) || !std::isfinite(stiffness) || !std::isfinite(rate))
  {
    throw std::invalid_argument("TissueDynamics: the stiffness and rate must be above 0");
  }
  // One step for all, a whole number of ticks: the solids step on the servo's clock, so that a
  // lockstep run is the same at any speed of the machine.
  const double ticks = std::round(tissues.front().settings.timeStep * rate);
  m_ticksPerStep = static_cast<int>(std::clamp(ticks, 1.0, 1e6));
  m_nextStepTick = static_cast<std::uint64_t>(m_ticksPerStep) - 1;
  m_tissues.reserve(tissues.size());
  for (TissueObject& given : tissues)
  {
    ElasticSolidSettings settings = given.settings;
    settings.timeStep = m_ticksPerStep / rate;
    Tissue tissue;
    tissue.object = given.object;
    tissue.handedOver = given.tets.points;
    tissue.solid = std::make_unique<ElasticSolid>(given.tets, given.materials, settings);
    for (const std::uint32_t vertex : given.fixedVertices)
    {
      if (vertex >= given.tets.points.size())
      {
        throw std::invalid_argument("TissueDynamics: fixed vertex " + std::to_string(vertex) +
                                    " of " + std::to_string(given.tets.points.size()));
      }
      tissue.solid->fixVertex(vertex);
    }
    m_tissues.push_back(std::move(tissue));
  }
}

TissueDynamics::~TissueDynamics()
{
  if (m_solidThread.joinable())
  {
    m_stopping.store(true, std::memory_order_release);
    m_requested.fetch_add(1, std::memory_order_acq_rel);
    wakeAllSleepers(m_requested);
    m_solidThread.join();
  }
}

void TissueDynamics::runStepsOnOwnThread(int fifoPriority)
{
  if (!m_solidThread.joinable())
  {
    m_solidThread = std::thread([this] { solidThreadLoop(); });
  }
  if (fifoPriority > 0)
  {
    // Refused without the privilege, as the loops' request is (their runner says so): the
    // solids then step at normal priority, and a loaded machine lags their surface more.
    requestFifoScheduling(m_solidThread, fifoPriority);
  }
}

void TissueDynamics::solidThreadLoop()
{
  std::uint32_t done = m_completed.load(std::memory_order_acquire);
  for (;;)
  {
    const std::uint32_t wanted = m_requested.load(std::memory_order_acquire);
    if (m_stopping.load(std::memory_order_acquire))
    {
      return;
    }
    if (wanted == done)
    {
      // Woken by launch() at once; the limit only bounds a wait that missed its wake-up.
      sleepWhileUnchanged(m_requested, wanted, std::chrono::milliseconds(100));
      continue;
    }
    stepLaunchedSolids();
    done = wanted;
    m_completed.store(done, std::memory_order_release);
    wakeAllSleepers(m_completed); // for waitForSolids(); no haptic thread sleeps on it
  }
}

void TissueDynamics::waitForSolids() const
{
  for (;;)
  {
    const std::uint32_t done = m_completed.load(std::memory_order_acquire);
    if (done == m_launched || !m_solidThread.joinable())
    {
      return;
    }
    sleepWhileUnchanged(m_completed, done, std::chrono::milliseconds(10));
  }
}

bool TissueDynamics::launchedStepDone() const
{
  return m_completed.load(std::memory_order_acquire) == m_launched;
}

void TissueDynamics::stepLaunchedSolids()
{
  for (Tissue& tissue : m_tissues)
  {
    if (tissue.launched)
    {
      tissue.solid->step();
    }
  }
}

void TissueDynamics::launch()
{
  for (std::size_t t = 0; t < m_tissues.size(); ++t)
  {
    TissueContact* contact = coupling(t);
    m_tissues[t].launched = contact != nullptr;
    if (contact != nullptr)
    {
      contact->loadStep();
    }
  }
  ++m_steps;
  ++m_launched;
  m_inFlight = true;
  if (m_solidThread.joinable())
  {
    m_requested.store(m_launched, std::memory_order_release);
    wakeAllSleepers(m_requested);
  }
  else
  {
    stepLaunchedSolids();
    m_completed.store(m_launched, std::memory_order_release);
  }
}

bool TissueDynamics::beforeUpdate(ProxySolver& solver, std::uint64_t tick)
{
  if (!m_inFlight)
  {
    return false;
  }
  if (!launchedStepDone())
  {
    // This update meets the surface before the step in flight, where lockstep would give it
    // the step's (a step launched at the last tick); it goes on with the older one, unwaited.
    ++m_staleUpdates;
    m_firstStaleUpdate = std::min(m_firstStaleUpdate, tick);
    return true;
  }
  const auto begin = std::chrono::steady_clock::now();
  handOver(solver);
  const auto end = std::chrono::steady_clock::now();
  m_handOverNanoseconds = std::chrono::duration_cast<std::chrono::nanoseconds>(end - begin).count();
  return false;
}

void TissueDynamics::handOver(ProxySolver& solver)
{
  for (std::size_t t = 0; t < m_tissues.size(); ++t)
  {
    Tissue& tissue = m_tissues[t];
    if (!tissue.launched)
    {
      continue;
    }
    // The ticks since the launch pressed the surface the solver still has.
    if (TissueContact* contact = coupling(t))
    {
      contact->beforeSurfaceHandOver();
    }
    const std::vector<Vec3>& positions = tissue.solid->positions();
    std::copy(positions.begin(), positions.end(), tissue.handedOver.begin());
    solver.setObjectPoints(tissue.object, positions.data(), positions.size());
    tissue.reading.maxDisplacement = tissue.solid->maxDisplacement();
  }
  m_inFlight = false;
  publishSurfaces(m_launchTick);
}

std::vector<std::uint32_t> TissueDynamics::deformingObjects() const
{
  std::vector<std::uint32_t> objects;
  objects.reserve(m_tissues.size());
  for (const Tissue& tissue : m_tissues)
  {
    objects.push_back(tissue.object);
  }
  return objects;
}

struct TissueDynamics::Binding : SceneBinding
{
  std::vector<std::unique_ptr<TissueContact>> contacts;
};

std::unique_ptr<TickDynamics::SceneBinding> TissueDynamics::prepare(const CollisionScene& scene)
{
  auto binding = std::make_unique<Binding>();
  for (Tissue& tissue : m_tissues)
  {
    binding->contacts.push_back(
      std::make_unique<TissueContact>(*tissue.solid, scene, tissue.object, m_stiffness));
  }
  return binding;
}

void TissueDynamics::install(ProxySolver& solver, SceneBinding* binding)
{
  // Installed once per scene, never per tick: the cast's cost is no tick's.
  m_binding = dynamic_cast<Binding*>(binding);
  if (m_binding != nullptr && m_binding->contacts.size() == m_tissues.size())
  {
    for (const std::unique_ptr<TissueContact>& contact : m_binding->contacts)
    {
      // Made by prepare() for this scene, with the runner making these objects deforming, so
      // each binds; one that did not is left out of step() (its tissue stays as it is).
      contact->bind(solver);
    }
  }
  else
  {
    m_binding = nullptr;
  }
  placeBodies(solver);
}

TissueContact* TissueDynamics::coupling(std::size_t k) const
{
  if (m_binding == nullptr)
  {
    return nullptr;
  }
  TissueContact* contact = m_binding->contacts[k].get();
  return contact->bound() ? contact : nullptr;
}

void TissueDynamics::publishSurfaces(std::uint64_t tick)
{
  Surfaces& surfaces = m_surfaces.back();
  surfaces.tick = tick;
  surfaces.steps = m_steps;
  for (std::size_t k = 0; k < m_tissues.size(); ++k)
  {
    const std::vector<Vec3>& points = m_tissues[k].handedOver;
    std::copy(points.begin(), points.end(), surfaces.points[k].begin());
  }
  m_surfaces.publish();
}

void TissueDynamics::placeBodies(ProxySolver& solver) const
{
  // The surfaces handed over, never the solids themselves, which their thread may be stepping.
  for (const Tissue& tissue : m_tissues)
  {
    solver.setObjectPoints(tissue.object, tissue.handedOver.data(), tissue.handedOver.size());
  }
}

double TissueDynamics::indentationAt(const Tissue& tissue, const ProxySolver& solver,
                                     std::uint32_t triangle, const Vec3& point,
                                     const Vec3& proxy) const
{
  // The contact point's weights on its triangle as it is now give the same material point at
  // rest, and the triangle's corners at rest its tangent plane there: the indentation is how far
  // the proxy's deepest point along that plane's normal lies below it (Hertz's d, for a surface
  // that was flat under the proxy).
  const TriangleMesh& mesh = solver.queryObject(tissue.object).mesh;
  const auto& corner = mesh.indices(triangle);
  const std::vector<Vec3>& now = mesh.points();
  const ClosestPointResult on =
    closestPointOnTriangle(point, now[corner[0]], now[corner[1]], now[corner[2]]);
  const std::vector<Vec3>& rest = tissue.solid->rest().points;
  const Vec3& a = rest[corner[0]];
  const Vec3& b = rest[corner[1]];
  const Vec3& c = rest[corner[2]];
  const Vec3 atRest = a * on.weights[0] + b * on.weights[1] + c * on.weights[2];
  const Vec3 across = cross(b - a, c - a);
  const double area = norm(across);
  if (!(area > 0.0))
  {
    return 0.0;
  }
  return dot(atRest - proxy, across / area) + solver.parameters().radius;
}

void TissueDynamics::step(HapticState& state, ProxySolver& solver)
{
  const auto begin = std::chrono::steady_clock::now();
  for (std::size_t t = 0; t < m_tissues.size(); ++t)
  {
    Tissue& tissue = m_tissues[t];
    TissueContact* coupled = coupling(t);
    if (coupled == nullptr)
    {
      continue;
    }
    // The spring's press on this tissue, plane by plane (eq. 19): kp mu_i along -n_i.
    Vec3 force;
    double deepest = 0.0;
    int deepestContact = -1; // the contact the spring presses hardest
    int firstContact = -1;   // any contact on the tissue, pressed or not
    for (int k = 0; k < state.numContacts; ++k)
    {
      const ContactSnapshot& contact = state.contacts[k];
      if (contact.object != tissue.object)
      {
        continue;
      }
      firstContact = firstContact >= 0 ? firstContact : k;
      if (contact.depth > 0.0)
      {
        force += contact.normal * (-m_stiffness * state.stiffnessScale * contact.depth);
        if (contact.depth > deepest)
        {
          deepest = contact.depth;
          deepestContact = k;
        }
      }
    }
    const double stiffness = deepestContact >= 0 ? m_stiffness * state.stiffnessScale : 0.0;
    coupled->addPress(state.proxy, force, stiffness);
    TissueReading& reading = tissue.reading;
    reading.force = norm(force);
    const int chosen = deepestContact >= 0 ? deepestContact : firstContact;
    reading.touched = chosen >= 0;
    reading.indentation = 0.0;
    if (reading.touched)
    {
      const ContactSnapshot& touched = state.contacts[chosen];
      reading.indentation =
        indentationAt(tissue, solver, touched.triangle, touched.point, state.proxy);
      tissue.deepest = std::max(tissue.deepest, reading.indentation);
    }
  }
  // On the servo's clock, not by counting calls: the solids step at the ticks whose number plus
  // one is a multiple of the step, so a threaded runner whose first update comes a few ticks in,
  // or which skips a finger sample, keeps lockstep's schedule (one step, under the mean of the
  // ticks it saw, when a skipped sample held a step's tick).
  // A clock that went back (a session placed again from tick 0) starts the schedule again.
  const std::uint64_t every = static_cast<std::uint64_t>(m_ticksPerStep);
  if (m_ticked && state.tick <= m_lastTick)
  {
    m_nextStepTick = (state.tick + every) / every * every - 1;
  }
  m_ticked = true;
  m_lastTick = state.tick;
  // At a step's tick the next step launches under the press of the ticks since. In lockstep it
  // steps here and is handed over at once; on the solids' thread it is handed over before the
  // first proxy update after it finished (beforeUpdate), which is the next one when it takes
  // less than a tick, as in lockstep. A step still running at the next step's tick is never
  // waited for: the press goes on summing and the next step launches once it is handed over.
  if (state.tick >= m_nextStepTick || m_launchLate)
  {
    if (m_inFlight && !launchedStepDone())
    {
      m_lateSteps += m_launchLate ? 0 : 1;
      m_launchLate = true;
    }
    else
    {
      if (m_inFlight)
      {
        handOver(solver);
      }
      m_launchLate = false;
      m_nextStepTick = (state.tick + 1 + every) / every * every - 1;
      m_launchTick = state.tick;
      launch();
      if (launchedStepDone())
      {
        handOver(solver);
      }
    }
  }
  const auto end = std::chrono::steady_clock::now();
  // A hand-over before this tick's update is this tick's dynamics too.
  state.dynamicsNanoseconds =
    std::chrono::duration_cast<std::chrono::nanoseconds>(end - begin).count() +
    m_handOverNanoseconds;
  m_handOverNanoseconds = 0;
}

} // namespace proxima
