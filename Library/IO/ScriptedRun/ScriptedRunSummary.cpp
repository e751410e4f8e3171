#include "IO/ScriptedRun/ScriptedRun.h"

#include <nlohmann/json.hpp>

#include <string>

namespace proxima
{
namespace
{
// The surface keys of the summary, for a one-mesh run and for each object of a scene alike.
void addSurfaceKeys(nlohmann::ordered_json& json, const LoadedObject& object,
                    const SurfaceMaterial& material)
{
  json["shading"] = object.shaded;
  json["point_normals"] = normalsSourceName(object.normals);
  if (object.normals == NormalsSource::Computed)
  {
    json["feature_angle_deg"] = object.featureAngleDegrees;
  }
  json["static_friction"] = material.staticFriction;
  json["dynamic_friction"] = material.dynamicFriction;
  json["viscosity_N_s_per_m"] = material.viscosity;
}

// A per-tick time as the summary gives it: median, p99, p99.9 and max of `quantile`.
template <typename Quantile>
nlohmann::ordered_json tickTimesJson(const Quantile& quantile)
{
  return {{"median", quantile(0.5)},
          {"p99", quantile(0.99)},
          {"p99.9", quantile(0.999)},
          {"max", quantile(1.0)}};
}

} // namespace

std::string scriptedRunSummaryJson(const ScriptedRunSettings& settings, const LoadedScene& loaded,
                                   const CollisionScene& scene, const ScriptedRunOutcome& outcome,
                                   const ScriptedRunReportContext& context,
                                   const std::string& realtimeJson)
{
  std::uint64_t numTriangles = 0;
  std::uint64_t numDegenerate = 0;
  for (const LoadedObject& object : loaded.objects)
  {
    numTriangles += object.numTriangles;
    numDegenerate += object.numDegenerateTriangles;
  }
  nlohmann::ordered_json json;
  if (settings.scene.empty())
  {
    json["mesh"] = settings.mesh;
  }
  else
  {
    json["scene"] = settings.scene;
  }
  json["path"] = settings.path;
  json["device"] = context.device;
  if (context.trace.empty())
  {
    json["trace"] = nullptr; // a library run keeps its ticks in memory
  }
  else
  {
    json["trace"] = context.trace;
  }
  json["triangles"] = numTriangles;
  json["degenerate_triangles"] = numDegenerate;
  json["radius_m"] = settings.radius;
  json["skin_m"] = outcome.skin;
  json["stiffness_N_per_m"] = settings.stiffness;
  json["rate_hz"] = settings.rate;
  json["mode"] = context.realtime ? "realtime" : "lockstep";
  if (settings.scene.empty())
  {
    // The keys of a one-mesh run, as before scene files.
    const LoadedObject& object = loaded.objects.front();
    const SurfaceMaterial& material = scene.objects.front().material;
    addSurfaceKeys(json, object, material);
    if (!settings.texture.empty())
    {
      nlohmann::ordered_json texture;
      texture["image"] = settings.texture;
      texture["role"] = settings.textureRole;
      if (material.textures.front().role == TextureRole::Bump)
      {
        texture["amplitude_m"] = material.textures.front().amplitude;
      }
      texture["channel"] = settings.textureChannel;
      json["texture"] = std::move(texture);
    }
  }
  else
  {
    nlohmann::ordered_json objects = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < loaded.objects.size(); ++i)
    {
      const LoadedObject& object = loaded.objects[i];
      const SurfaceMaterial& material = scene.objects[i].material;
      nlohmann::ordered_json entry;
      entry["mesh"] = object.mesh;
      entry["triangles"] = object.numTriangles;
      entry["degenerate_triangles"] = object.numDegenerateTriangles;
      addSurfaceKeys(entry, object, material);
      entry["textures"] = material.textures.size();
      objects.push_back(std::move(entry));
    }
    json["objects"] = std::move(objects);
  }
  json["ticks"] = outcome.summary.ticks();
  json["contact_ticks"] = outcome.summary.contactTicks();
  json["iterations"] = {{"total", outcome.summary.totalIterations()},
                        {"mean", outcome.summary.ticks() > 0
                                   ? static_cast<double>(outcome.summary.totalIterations()) /
                                       static_cast<double>(outcome.summary.ticks())
                                   : 0.0},
                        {"max", outcome.summary.maxIterations()},
                        {"cap", settings.maxIterations},
                        {"ticks_at_cap", outcome.summary.iterationCapTicks()}};
  json["refused_finger_ticks"] = outcome.summary.refusedTicks();
  json["contact_overflow_ticks"] = outcome.summary.overflowTicks();
  json["clamped_force_ticks"] = outcome.summary.clampedTicks();
  json["fading_force_ticks"] = outcome.summary.fadingTicks();
  json["device_lost_ticks"] = outcome.summary.deviceLostTicks();
  json["stuck_ticks"] = outcome.summary.stuckTicks();
  json["friction_limited_ticks"] = outcome.summary.frictionLimitedTicks();
  if (outcome.start.movedOutside)
  {
    json["started_inside"] = {
      {"object", outcome.start.object},
      {"winding_number", outcome.start.windingNumber},
      {"moved_m", outcome.start.movedDistance},
      {"proxy_start",
       {outcome.start.position.x, outcome.start.position.y, outcome.start.position.z}},
      {"ticks", outcome.summary.startedOutsideTicks()}};
  }
  else
  {
    json["started_inside"] = nullptr;
  }
  json["max_force_N"] = outcome.summary.maxForce();
  const RunSummary& summary = outcome.summary;
  json["solve_ns"] =
    tickTimesJson([&summary](double q) { return summary.solveNanosecondsQuantile(q); });
  json["triangles_tested_per_tick"] = outcome.summary.meanTrianglesTested();
  if (!outcome.bodies.empty())
  {
    // Paper section 6: where each body ended, its energy, and what the finger put into it.
    nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
    for (const BodyOutcome& body : outcome.bodies)
    {
      bodies.push_back({{"name", body.name},
                        {"object", body.object},
                        {"joint", body.joint},
                        {"q", body.jointPosition},
                        {"q_rate", body.jointVelocity},
                        {"kinetic_J", body.kinetic},
                        {"potential_J", body.potential},
                        {"work_by_finger_J", body.work}});
      // A body that left the scene's bounds is reported with when; one that stayed, null.
      if (body.leftBoundsAt >= 0.0)
      {
        bodies.back()["left_bounds_s"] = body.leftBoundsAt;
      }
      else
      {
        bodies.back()["left_bounds_s"] = nullptr;
      }
    }
    json["bodies"] = std::move(bodies);
    json["pushed_ticks"] = outcome.summary.pushedTicks();
    json["dynamics_ns"] =
      tickTimesJson([&summary](double q) { return summary.dynamicsNanosecondsQuantile(q); });
  }
  if (!outcome.tissues.empty())
  {
    // Documentation/Tissue.md: each solid's size, how often it stepped, and how far it gave way.
    nlohmann::ordered_json tissues = nlohmann::ordered_json::array();
    for (const TissueOutcome& tissue : outcome.tissues)
    {
      tissues.push_back({{"object", tissue.object},
                         {"tetrahedra", tissue.tetrahedra},
                         {"vertices", tissue.vertices},
                         {"fixed_vertices", tissue.fixedVertices},
                         {"ticks_per_step", tissue.ticksPerStep},
                         {"steps", tissue.steps},
                         {"late_steps", tissue.lateSteps},
                         {"stale_updates", tissue.staleUpdates},
                         {"deepest_indentation_m", tissue.deepestIndentation},
                         {"max_displacement_at_end_m", tissue.maxDisplacement},
                         {"energy_at_end_J", tissue.energy},
                         {"meshing_s", tissue.meshingSeconds}});
    }
    json["tissue"] = std::move(tissues);
    json["pushed_ticks"] = outcome.summary.pushedTicks();
    json["dynamics_ns"] =
      tickTimesJson([&summary](double q) { return summary.dynamicsNanosecondsQuantile(q); });
  }
  nlohmann::ordered_json budgetJson;
  budgetJson["tick_budget"] = outcome.budget.text();
  budgetJson["seconds"] = outcome.budget.seconds;
  budgetJson["iterations"] = outcome.budget.iterations;
  if (context.realtime && !(outcome.budget.seconds > 0.0) && outcome.budget.safetyCapSeconds > 0.0)
  {
    // The threaded runtime's wall-time cap beside an iteration budget (applyToRealTime).
    budgetJson["safety_cap_s"] = outcome.budget.safetyCapSeconds;
  }
  budgetJson["limited_ticks"] = outcome.summary.budgetLimitedTicks();
  if (context.realtime)
  {
    // A realtime tick cannot be replayed as it ran: its start and its budget were the clock's.
    budgetJson["residual_m"] = nullptr;
  }
  else
  {
    budgetJson["residual_m"] = {{"max", outcome.summary.budgetResidualQuantile(1.0)},
                                {"median", outcome.summary.budgetResidualQuantile(0.5)}};
  }
  nlohmann::ordered_json histogram = nlohmann::ordered_json::object();
  for (const auto& [ticks, runs] : outcome.summary.recoveryHistogram())
  {
    histogram[std::to_string(ticks)] = runs;
  }
  budgetJson["recovery_ticks"] = {
    {"runs", outcome.summary.recoveries()},
    {"max", outcome.summary.recoveryTicksQuantile(1.0)},
    {"p99", outcome.summary.recoveryTicksQuantile(0.99)},
    {"histogram", std::move(histogram)},
    {"unrecovered_at_end", outcome.summary.unrecoveredLimitedTicks()}};
  budgetJson["replay_ms"] = outcome.replayMilliseconds;
  json["budget"] = std::move(budgetJson);
  json["read_ms"] = context.readMilliseconds;
  json["tree_build_ms"] = loaded.treeBuildMilliseconds;
  json["run_ms"] = outcome.runMilliseconds;
  if (!realtimeJson.empty())
  {
    json["realtime"] = nlohmann::ordered_json::parse(realtimeJson);
  }

  return json.dump(2) + "\n";
}

} // namespace proxima
