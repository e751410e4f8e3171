#include "LoopReport.h"

#include <cstdio>

namespace proxima::cli
{

nlohmann::ordered_json loopJson(const LoopStatistics& statistics, const std::string& scheduling)
{
  nlohmann::ordered_json json;
  if (!scheduling.empty())
  {
    json["scheduling"] = scheduling;
  }
  json["ticks"] = statistics.ticks;
  json["wake_ups"] = statistics.wakeUps;
  json["late_wake_ups"] = statistics.lateWakeUps;
  json["missed_deadlines"] = statistics.missedDeadlines;
  json["over_budget_ticks"] = statistics.overBudgetTicks;
  json["wake_latency_us"] = {
    {"p50", statistics.wakeLatencyQuantileNanoseconds(0.5) / 1e3},
    {"p99", statistics.wakeLatencyQuantileNanoseconds(0.99) / 1e3},
    {"p99.9", statistics.wakeLatencyQuantileNanoseconds(0.999) / 1e3},
    {"max", static_cast<double>(statistics.maxWakeLatencyNanoseconds) / 1e3}};
  json["jitter_us"] = {{"p50", statistics.jitterQuantileNanoseconds(0.5) / 1e3},
                       {"p99", statistics.jitterQuantileNanoseconds(0.99) / 1e3},
                       {"max", statistics.jitterQuantileNanoseconds(1.0) / 1e3}};
  json["max_work_us"] = static_cast<double>(statistics.maxWorkNanoseconds) / 1e3;
  return json;
}

std::string deadlineLine(const LoopStatistics& statistics)
{
  const double percent = statistics.wakeUps > 0
                           ? 100.0 * static_cast<double>(statistics.lateWakeUps) /
                               static_cast<double>(statistics.wakeUps)
                           : 0.0;
  char text[160];
  std::snprintf(text, sizeof text, "woke late %llu of %llu times (%.2f %%), missed %llu deadlines",
                static_cast<unsigned long long>(statistics.lateWakeUps),
                static_cast<unsigned long long>(statistics.wakeUps), percent,
                static_cast<unsigned long long>(statistics.missedDeadlines));
  return text;
}

} // namespace proxima::cli
