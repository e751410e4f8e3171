// How a real-time loop ran, for the commands that run the threaded runtime (run --realtime and
// serve --device): its statistics as the summary's JSON, and the one human line of its wake-ups
// and deadlines.
#pragma once

#include "Runtime/LoopStatistics.h"

#include <nlohmann/json.hpp>

#include <string>

namespace proxima::cli
{

/// Ticks, wake-ups, late wake-ups, missed deadlines, ticks over budget, wake-up latency and
/// jitter quantiles (us), the longest tick's work; with the loop's scheduling when given.
nlohmann::ordered_json loopJson(const LoopStatistics& statistics,
                                const std::string& scheduling = {});

/// "woke late 12 of 29001 times (0.04 %), missed 30 deadlines": the human line's figures.
std::string deadlineLine(const LoopStatistics& statistics);

} // namespace proxima::cli
