#include "ScriptedHarness.h"

#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

namespace proxima::scripted
{
namespace
{
// Plays the scripted path and reports a NaN finger on the chosen ticks.
class ScriptedDevice final : public HapticDevice
{
public:
  ScriptedDevice(FingerPath path, const std::set<std::uint64_t>& nanTicks,
                 const std::map<std::uint64_t, Vec3>& overrides, double startTime, double rate)
    : m_device(std::move(path))
    , m_nanTicks(nanTicks)
    , m_overrides(overrides)
    , m_startTime(startTime)
    , m_rate(rate)
  {}
  DeviceSample read(double time) override
  {
    DeviceSample sample = m_device.read(time);
    const auto tick = static_cast<std::uint64_t>(std::llround((time - m_startTime) * m_rate));
    if (const auto found = m_overrides.find(tick); found != m_overrides.end())
    {
      sample.position = found->second;
    }
    if (m_nanTicks.count(tick) != 0)
    {
      sample.position.x = std::nan("");
    }
    return sample;
  }
  void writeForce(const Vec3& force, double time) override { m_device.writeForce(force, time); }

private:
  SimulatedDevice m_device;
  std::set<std::uint64_t> m_nanTicks;
  std::map<std::uint64_t, Vec3> m_overrides;
  double m_startTime;
  double m_rate;
};

Vec3 clearStart(const oracle::MeshOracle& oracle, Vec3 start, double radius)
{
  for (int step = 0; step < 1000 && oracle.distance(start, 2.0 * radius) < 1.5 * radius; ++step)
  {
    start.z += radius;
  }
  return start;
}

std::string goldenPath(const std::string& name)
{
  return std::string(PROXIMA_SOURCE_DIR) + "/Testing/ScriptedPaths/Golden/" + name + ".csv";
}

std::vector<std::vector<double>> parseCsv(const std::string& text, std::string& header)
{
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::getline(in, header);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.empty())
    {
      continue;
    }
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ','))
    {
      row.push_back(std::strtod(field.c_str(), nullptr));
    }
    rows.push_back(row);
  }
  return rows;
}
} // namespace

ScriptedOutcome runScriptedCase(const ScriptedCase& c)
{
  ScriptedOutcome outcome;
  const auto begin = std::chrono::steady_clock::now();
  const oracle::MeshOracle& oracle = *c.oracle;

  ProxySolver solver;
  solver.setScene(c.scene, c.proxy);
  outcome.skin = solver.skin();
  outcome.start = c.start ? *c.start : clearStart(oracle, c.path.positions.front(), c.proxy.radius);
  solver.resetProxy(outcome.start);

  const oracle::OracleSettings settings =
    oracle::OracleSettings::forScene(c.scene->diagonal(), solver.skin());
  oracle::TickChecker checker(oracle, *c.scene, c.proxy, settings);
  checker.reset(outcome.start);

  LockstepSettings lockstep;
  lockstep.rate = c.rate;
  lockstep.startTime = c.path.startTime();
  lockstep.numTicks = ticksCovering(c.path.startTime(), c.path.endTime(), c.rate);
  ScriptedDevice device(c.path, c.nanTicks, c.fingerOverrides, lockstep.startTime, c.rate);

  oracle::InvariantStats& stats = checker.stats();
  Vec3 previousForce;
  runLockstep(lockstep, solver, device, c.servo, [&](const HapticState& record) {
    checker.check(record.tick, record.finger, record.proxy, record.iterations, record.numContacts,
                  record.conditions.has(TickCondition::fingerRefused),
                  record.conditions.has(TickCondition::hitIterationCap),
                  record.conditions.has(TickCondition::contactOverflow),
                  record.conditions.has(TickCondition::budgetLimited));
    // (e) Force: kp (proxy - finger) clamped to the device limit, or the last force held.
    const std::string where = "tick " + std::to_string(record.tick);
    const auto overridden = c.fingerOverrides.find(record.tick);
    const bool nanTick =
      c.nanTicks.count(record.tick) != 0 ||
      (overridden != c.fingerOverrides.end() &&
       !(std::isfinite(overridden->second.x) && std::isfinite(overridden->second.y) &&
         std::isfinite(overridden->second.z)));
    if (nanTick != record.conditions.has(TickCondition::fingerRefused))
    {
      stats.fail(stats.refusalFailures, where + ": finger " + oracle::str(record.finger) +
                                          (nanTick ? " was not refused" : " was refused"));
    }
    oracle::ForceTick force;
    force.proxy = record.proxy;
    force.finger = record.finger;
    force.force = record.force;
    force.previousForce = previousForce;
    force.refused = record.conditions.has(TickCondition::fingerRefused);
    force.clamped = record.conditions.has(TickCondition::forceClamped);
    force.ramped = record.conditions.has(TickCondition::forceRateLimited) ||
                   record.conditions.has(TickCondition::forceFading);
    force.inContact = record.numContacts > 0;
    oracle::checkServoForce(stats, where, force, c.servo.stiffness, c.servo.maxForce);
    previousForce = record.force;
    if (c.keepTrace)
    {
      outcome.trace.push_back(record);
    }
  });
  outcome.stats = stats;
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return outcome;
}

void expectInvariants(const std::string& name, const ScriptedOutcome& outcome)
{
  const oracle::InvariantStats& s = outcome.stats;
  std::cout << s.summary(name) << "[oracle] " << name << ": skin " << outcome.skin
            << " m, wall time " << outcome.seconds << " s\n";
  testing::Test::RecordProperty("ticks", std::to_string(s.ticks));
  testing::Test::RecordProperty("min_clearance_m", oracle::str(s.minClearance));
  testing::Test::RecordProperty("min_sweep_clearance_m", oracle::str(s.minSweepClearance));
  testing::Test::RecordProperty("max_residual_m", oracle::str(s.maxResidual));
  testing::Test::RecordProperty("max_gap_m", oracle::str(s.maxGap));
  testing::Test::RecordProperty("max_free_path_error_m", oracle::str(s.maxFreePathError));
  testing::Test::RecordProperty("max_iterations", std::to_string(s.maxIterations));
  testing::Test::RecordProperty("iteration_cap_ticks", std::to_string(s.capTicks));
  testing::Test::RecordProperty("budget_limited_ticks", std::to_string(s.budgetLimitedTicks));
  testing::Test::RecordProperty("cap_lag_m", oracle::str(s.maxCapLag));
  EXPECT_GT(s.ticks, 0u) << name;
  EXPECT_EQ(s.penetrations, 0u) << name << ": (a) penetration";
  EXPECT_EQ(s.crossings, 0u) << name << ": (b) a move crossed a triangle";
  EXPECT_EQ(s.tunnels, 0u) << name << ": (b) a move passed within the radius";
  EXPECT_EQ(s.freePathFailures, 0u) << name << ": (c) free path not taken";
  EXPECT_EQ(s.residualFailures, 0u) << name << ": (d) not a local minimum";
  EXPECT_EQ(s.forceFailures, 0u) << name << ": (e) force";
  EXPECT_EQ(s.gapFailures, 0u) << name << ": (f) contact gap";
  EXPECT_EQ(s.refusalFailures, 0u) << name << ": NaN finger handling";
  EXPECT_EQ(s.replayFailures, 0u) << name << ": replay (determinism)";
  EXPECT_EQ(s.approachFailures, 0u) << name << ": a move stage went away from the finger";
  EXPECT_EQ(s.nonTerminating, 0u) << name << ": the move/update loop does not terminate";
  EXPECT_EQ(s.overflowTicks, 0u) << name << ": contact buffers overflowed";
  EXPECT_EQ(s.coverageFailures, 0u) << name << ": the trace is not every tick of its path";
  EXPECT_EQ(s.settleFailures, 0u) << name << ": (h) budget-limited long after the finger rested";
}

std::string goldenCsv(const std::vector<HapticState>& trace)
{
  std::string text =
    "tick,t,finger_x,finger_y,finger_z,proxy_x,proxy_y,proxy_z,force_x,force_y,force_z,"
    "contacts,iterations\n";
  char line[512];
  for (const HapticState& r : trace)
  {
    std::snprintf(line, sizeof line,
                  "%llu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d\n",
                  static_cast<unsigned long long>(r.tick), r.time, r.finger.x, r.finger.y,
                  r.finger.z, r.proxy.x, r.proxy.y, r.proxy.z, r.force.x, r.force.y, r.force.z,
                  r.numContacts, r.iterations);
    text += line;
  }
  return text;
}

// Regenerate with: PROXIMA_UPDATE_GOLDEN=1 ctest --test-dir build -R Golden (then review the
// diff of Testing/ScriptedPaths/Golden/ before committing: a golden trace changes only on purpose).
void expectMatchesGolden(const std::string& name, const std::vector<HapticState>& trace)
{
  const std::string path = goldenPath(name);
  const std::string actual = goldenCsv(trace);
  const char* update = std::getenv("PROXIMA_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1")
  {
    std::ofstream out(path, std::ios::binary);
    out << actual;
    ASSERT_TRUE(out.good()) << "could not write " << path;
    std::cout << "[golden] rewrote " << path << " (" << trace.size() << " ticks)\n";
    return;
  }
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in.good()) << "golden trace missing: " << path
                         << " (run with PROXIMA_UPDATE_GOLDEN=1 to create it)";
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string expectedHeader;
  std::string actualHeader;
  const auto expected = parseCsv(buffer.str(), expectedHeader);
  const auto got = parseCsv(actual, actualHeader);
  ASSERT_EQ(expectedHeader, actualHeader) << path;
  ASSERT_EQ(expected.size(), got.size()) << path << ": tick count differs";
  // 1e-12 relative to the larger of the two values and of the column's largest magnitude, so a
  // force component passing through zero is compared at the scale of the forces, not of zero.
  const std::size_t columns = expected.empty() ? 0 : expected.front().size();
  std::vector<double> scale(columns, 0.0);
  for (const auto& row : expected)
  {
    for (std::size_t k = 0; k < row.size() && k < columns; ++k)
    {
      scale[k] = std::max(scale[k], std::fabs(row[k]));
    }
  }
  int reported = 0;
  std::size_t mismatches = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    ASSERT_EQ(expected[i].size(), got[i].size()) << path << " row " << i;
    for (std::size_t k = 0; k < columns; ++k)
    {
      const double a = expected[i][k];
      const double b = got[i][k];
      const bool integer = k == 0 || k >= 11; // tick, contacts, iterations
      const double tolerance =
        integer ? 0.0 : 1e-12 * std::max({std::fabs(a), std::fabs(b), scale[k]});
      const double difference = std::fabs(a - b);
      if (scale[k] > 0.0)
      {
        worst = std::max(worst, difference / scale[k]);
      }
      if (difference > tolerance)
      {
        ++mismatches;
        if (reported++ < 10)
        {
          ADD_FAILURE() << path << ": tick " << i << " column " << k << " is " << oracle::str(b)
                        << ", golden " << oracle::str(a);
        }
      }
    }
  }
  std::cout << "[golden] " << name << ": " << expected.size() << " ticks, " << mismatches
            << " mismatches, worst difference " << worst << " of the column scale\n";
  EXPECT_EQ(mismatches, 0u) << path;
}

} // namespace proxima::scripted
