// proxima._proxima.check_trace: the verdict of the scripted suites' oracle (Testing/ScriptedPaths/
// ProxyOracle.h: CGAL's AABB tree, exact predicates, an exact QP; written apart from the solver)
// on a trace, whoever produced it: every tick of the path at the run's rate, no penetration, no
// tunnelling, the local minimum reached, and the servo's force for the proxy and the finger.
#include "Bindings.h"

#include "IO/InputChecks/InputError.h"
#include "ProxyOracle.h"
#include "Proxy/ProxySolver.h"
#include "Proxy/ProxyStart.h"
#include "Runtime/LockstepRuntime.h"

#include <memory>
#include <vector>

namespace proxima::python
{
namespace
{
template <typename T>
py::array_t<T, py::array::c_style | py::array::forcecast> traceColumn(const py::dict& trace,
                                                                      const char* name,
                                                                      py::ssize_t rows)
{
  if (!trace.contains(name))
  {
    throw InputError("trace", std::string("has no column '") + name + "'");
  }
  auto column = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(trace[name]);
  if (!column || column.ndim() != 1 || (rows >= 0 && column.shape(0) != rows))
  {
    throw InputError("trace", std::string("column '") + name + "' is not a column of every tick");
  }
  return column;
}

py::dict verdict(const oracle::InvariantStats& stats)
{
  py::dict result;
  result["passed"] = stats.failures() == 0;
  result["failures"] = stats.failures();
  result["ticks"] = stats.ticks;
  result["contact_ticks"] = stats.contactTicks;
  result["penetrations"] = stats.penetrations;
  result["crossings"] = stats.crossings;
  result["tunnels"] = stats.tunnels;
  result["free_path_failures"] = stats.freePathFailures;
  result["local_minimum_failures"] = stats.residualFailures;
  result["gap_failures"] = stats.gapFailures;
  result["replay_failures"] = stats.replayFailures;
  result["force_failures"] = stats.forceFailures;
  result["coverage_failures"] = stats.coverageFailures;
  result["approach_failures"] = stats.approachFailures;
  result["non_terminating"] = stats.nonTerminating;
  result["budget_limited_ticks"] = stats.budgetLimitedTicks;
  result["min_clearance_m"] = stats.minClearance;
  result["min_sweep_clearance_m"] = stats.minSweepClearance;
  result["max_residual_m"] = stats.maxResidual;
  result["max_free_path_error_m"] = stats.maxFreePathError;
  result["messages"] = stats.messages;
  return result;
}
} // namespace

void addOracleBindings(py::module_& module)
{
  module.def(
    "check_trace",
    [](const py::dict& trace, const py::object& path, const py::kwargs& keywords) {
      ScriptedRunSettings settings = settingsFromKeywords(keywords);
      const FingerPath fingerPath = fingerPathFrom(path, settings);
      const auto tick = traceColumn<std::uint64_t>(trace, "tick", -1);
      const py::ssize_t rows = tick.shape(0);
      const auto time = traceColumn<double>(trace, "t", rows);
      const auto fingerX = traceColumn<double>(trace, "finger_x", rows);
      const auto fingerY = traceColumn<double>(trace, "finger_y", rows);
      const auto fingerZ = traceColumn<double>(trace, "finger_z", rows);
      const auto proxyX = traceColumn<double>(trace, "proxy_x", rows);
      const auto proxyY = traceColumn<double>(trace, "proxy_y", rows);
      const auto proxyZ = traceColumn<double>(trace, "proxy_z", rows);
      const auto forceX = traceColumn<double>(trace, "force_x", rows);
      const auto forceY = traceColumn<double>(trace, "force_y", rows);
      const auto forceZ = traceColumn<double>(trace, "force_z", rows);
      const auto iterations = traceColumn<std::int32_t>(trace, "iterations", rows);
      const auto contacts = traceColumn<std::int32_t>(trace, "contacts", rows);
      const auto flags = traceColumn<std::uint32_t>(trace, "flags", rows);

      // The rows as plain values, so that the check runs without the interpreter's lock.
      struct Row
      {
        std::uint64_t tick;
        double time;
        Vec3 finger;
        Vec3 proxy;
        Vec3 force;
        int iterations;
        int contacts;
        std::uint32_t flags;
      };
      std::vector<Row> table(static_cast<std::size_t>(rows));
      for (py::ssize_t row = 0; row < rows; ++row)
      {
        table[static_cast<std::size_t>(row)] =
          Row{tick.at(row),
              time.at(row),
              Vec3{fingerX.at(row), fingerY.at(row), fingerZ.at(row)},
              Vec3{proxyX.at(row), proxyY.at(row), proxyZ.at(row)},
              Vec3{forceX.at(row), forceY.at(row), forceZ.at(row)},
              iterations.at(row),
              contacts.at(row),
              flags.at(row)};
      }
      oracle::InvariantStats stats;
      {
        py::gil_scoped_release released;
        LoadedScene loaded = loadScene(settings);
        refuseSceneBodies(loaded, "the oracle check");
        refuseSceneTissue(loaded, "the oracle check");
        const CollisionScene& scene = *loaded.scene;
        ProxyParameters parameters = proxyParameters(settings);
        tickBudget(settings, TickWorkBudget{}).applyTo(parameters);
        auto solver = std::make_unique<ProxySolver>();
        solver->setScene(&scene, parameters);
        // The oracle's own view of the scene: its triangles in CGAL's tree, its tolerances.
        const oracle::MeshOracle meshOracle(scene);
        const oracle::OracleSettings oracleSettings =
          oracle::OracleSettings::forScene(meshOracle.diagonal(), solver->skin());
        oracle::TickChecker checker(meshOracle, scene, parameters, oracleSettings);
        // Where the run put the proxy before its first tick (ProxyStart.h).
        checker.reset(placeProxyStart(scene, parameters, fingerPath.positions.front()).position);
        oracle::InvariantStats& checked = checker.stats();
        // Coverage: the run plays every tick of the path at its rate, tick i at
        // start + i / rate with the finger where the path is then.
        const double rate = settings.rate;
        const std::uint64_t expected =
          ticksCovering(fingerPath.startTime(), fingerPath.endTime(), rate);
        if (table.size() != expected)
        {
          checked.fail(checked.coverageFailures, "the trace has " + std::to_string(table.size()) +
                                                   " ticks, but the path at " + oracle::str(rate) +
                                                   " Hz has " + std::to_string(expected));
        }
        // Whether a surface material may scale kp at a contact, by an amount no column holds.
        bool knownStiffness = settings.textureRole != "stiffness";
        for (const CollisionObject& object : scene.objects)
        {
          knownStiffness = knownStiffness && object.material.stiffness == 1.0 &&
                           object.material.stiffnessRegions.empty();
          for (const TextureMap& map : object.material.textures)
          {
            knownStiffness = knownStiffness && map.role != TextureRole::Stiffness;
          }
        }
        const ServoParameters servo = servoParameters(settings);
        std::size_t hint = 0;
        Vec3 previousForce;
        std::uint64_t index = 0;
        for (const Row& row : table)
        {
          const std::string where = "tick " + std::to_string(row.tick);
          const double at = fingerPath.startTime() + static_cast<double>(index) / rate;
          const Vec3 sampled = fingerPath.positionAt(at, hint);
          if (checked.coverageFailures == 0 &&
              (row.tick != index || row.time != at || row.finger != sampled))
          {
            checked.fail(checked.coverageFailures,
                         "row " + std::to_string(index) + " is " + where +
                           " at t = " + oracle::str(row.time) + " s with the finger at " +
                           oracle::str(row.finger) + ", but the path's tick " +
                           std::to_string(index) + " is at t = " + oracle::str(at) +
                           " s with the finger at " + oracle::str(sampled));
          }
          ++index;
          const TickConditions conditions(row.flags);
          const bool refused = conditions.has(TickCondition::fingerRefused);
          checker.check(row.tick, row.finger, row.proxy, row.iterations, row.contacts, refused,
                        conditions.has(TickCondition::hitIterationCap),
                        conditions.has(TickCondition::contactOverflow),
                        conditions.has(TickCondition::budgetLimited));
          oracle::ForceTick force;
          force.proxy = row.proxy;
          force.finger = row.finger;
          force.force = row.force;
          force.previousForce = previousForce;
          force.refused = refused;
          force.clamped = conditions.has(TickCondition::forceClamped);
          force.ramped =
            conditions.hasAny(TickCondition::forceRateLimited | TickCondition::forceFading);
          force.knownStiffness = knownStiffness;
          force.inContact = row.contacts > 0;
          oracle::checkServoForce(checked, where, force, servo.stiffness, servo.maxForce);
          previousForce = row.force;
        }
        stats = checker.stats();
      }
      return verdict(stats);
    },
    py::arg("trace"), py::arg("path"),
    "The oracle's verdict on a trace (columns as run returns them) of `path` through the mesh or "
    "scene of the keywords: a dict of failures and worst margins, with 'passed'.");
}

} // namespace proxima::python
