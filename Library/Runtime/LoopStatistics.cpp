#include "Runtime/LoopStatistics.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace proxima
{
namespace
{
double quantileOfBins(std::vector<std::pair<double, std::uint64_t>> bins, double q)
{
  std::sort(bins.begin(), bins.end());
  std::uint64_t total = 0;
  for (const auto& bin : bins)
  {
    total += bin.second;
  }
  if (total == 0)
  {
    return 0.0;
  }
  const auto rank = static_cast<std::uint64_t>(
    std::max(1.0, std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(total))));
  std::uint64_t seen = 0;
  for (const auto& bin : bins)
  {
    seen += bin.second;
    if (seen >= rank)
    {
      return bin.first;
    }
  }
  return bins.back().first;
}

void storeMax(std::atomic<std::int64_t>& target, std::int64_t value)
{
  // One writer: a plain load and store is enough.
  if (value > target.load(std::memory_order_relaxed))
  {
    target.store(value, std::memory_order_relaxed);
  }
}
} // namespace

double LoopStatistics::periodQuantileNanoseconds(double q) const
{
  std::vector<std::pair<double, std::uint64_t>> bins;
  bins.reserve(kBins);
  for (int i = 0; i < kBins; ++i)
  {
    bins.emplace_back(static_cast<double>((i + 1) * kBinNanoseconds), periodHistogram[i]);
  }
  return quantileOfBins(std::move(bins), q);
}

double LoopStatistics::jitterQuantileNanoseconds(double q) const
{
  const double nominal = rate > 0.0 ? 1e9 / rate : 0.0;
  std::vector<std::pair<double, std::uint64_t>> bins;
  bins.reserve(kBins);
  for (int i = 0; i < kBins; ++i)
  {
    // The bin's centre stands for its periods: half a bin of resolution.
    const double centre = (static_cast<double>(i) + 0.5) * static_cast<double>(kBinNanoseconds);
    bins.emplace_back(std::abs(centre - nominal), periodHistogram[i]);
  }
  return quantileOfBins(std::move(bins), q);
}

double LoopStatistics::wakeLatencyQuantileNanoseconds(double q) const
{
  std::vector<std::pair<double, std::uint64_t>> bins;
  bins.reserve(kWakeBins);
  for (int i = 0; i + 1 < kWakeBins; ++i)
  {
    bins.emplace_back(static_cast<double>((i + 1) * kBinNanoseconds), wakeLatencyHistogram[i]);
  }
  bins.emplace_back(std::max(static_cast<double>(kWakeBins * kBinNanoseconds),
                             static_cast<double>(maxWakeLatencyNanoseconds)),
                    wakeLatencyHistogram[kWakeBins - 1]);
  return quantileOfBins(std::move(bins), q);
}

void LoopStatisticsRecorder::reset(double rate)
{
  m_rate.store(rate, std::memory_order_relaxed);
  m_ticks.store(0, std::memory_order_relaxed);
  m_missed.store(0, std::memory_order_relaxed);
  m_minPeriod.store(0, std::memory_order_relaxed);
  m_maxPeriod.store(0, std::memory_order_relaxed);
  m_maxWork.store(0, std::memory_order_relaxed);
  m_overBudget.store(0, std::memory_order_relaxed);
  for (auto& bin : m_histogram)
  {
    bin.store(0, std::memory_order_relaxed);
  }
  m_wakeUps.store(0, std::memory_order_relaxed);
  m_lateWakeUps.store(0, std::memory_order_relaxed);
  m_maxWakeLatency.store(0, std::memory_order_relaxed);
  for (auto& bin : m_wakeHistogram)
  {
    bin.store(0, std::memory_order_relaxed);
  }
}

void LoopStatisticsRecorder::record(std::int64_t periodNanoseconds, bool missed)
{
  const std::int64_t bin = std::clamp<std::int64_t>(
    periodNanoseconds / LoopStatistics::kBinNanoseconds, 0, LoopStatistics::kBins - 1);
  m_histogram[static_cast<std::size_t>(bin)].fetch_add(1, std::memory_order_relaxed);
  const std::uint64_t ticks = m_ticks.fetch_add(1, std::memory_order_relaxed);
  if (ticks == 0 || periodNanoseconds < m_minPeriod.load(std::memory_order_relaxed))
  {
    m_minPeriod.store(periodNanoseconds, std::memory_order_relaxed);
  }
  storeMax(m_maxPeriod, periodNanoseconds);
  if (missed)
  {
    m_missed.fetch_add(1, std::memory_order_relaxed);
  }
}

void LoopStatisticsRecorder::recordWork(std::int64_t workNanoseconds)
{
  storeMax(m_maxWork, workNanoseconds);
  const double rate = m_rate.load(std::memory_order_relaxed);
  if (rate > 0.0 && static_cast<double>(workNanoseconds) > 1e9 / rate)
  {
    m_overBudget.fetch_add(1, std::memory_order_relaxed);
  }
}

void LoopStatisticsRecorder::recordMissed(std::uint64_t count)
{
  m_missed.fetch_add(count, std::memory_order_relaxed);
}

void LoopStatisticsRecorder::recordWakeUp(std::int64_t latencyNanoseconds, bool late)
{
  const std::int64_t bin = std::clamp<std::int64_t>(
    latencyNanoseconds / LoopStatistics::kBinNanoseconds, 0, LoopStatistics::kWakeBins - 1);
  m_wakeHistogram[static_cast<std::size_t>(bin)].fetch_add(1, std::memory_order_relaxed);
  m_wakeUps.fetch_add(1, std::memory_order_relaxed);
  if (late)
  {
    m_lateWakeUps.fetch_add(1, std::memory_order_relaxed);
  }
  storeMax(m_maxWakeLatency, latencyNanoseconds);
}

LoopStatistics LoopStatisticsRecorder::snapshot() const
{
  LoopStatistics statistics;
  statistics.rate = m_rate.load(std::memory_order_relaxed);
  statistics.ticks = m_ticks.load(std::memory_order_relaxed);
  statistics.missedDeadlines = m_missed.load(std::memory_order_relaxed);
  statistics.minPeriodNanoseconds = m_minPeriod.load(std::memory_order_relaxed);
  statistics.maxPeriodNanoseconds = m_maxPeriod.load(std::memory_order_relaxed);
  statistics.maxWorkNanoseconds = m_maxWork.load(std::memory_order_relaxed);
  statistics.overBudgetTicks = m_overBudget.load(std::memory_order_relaxed);
  for (int i = 0; i < LoopStatistics::kBins; ++i)
  {
    statistics.periodHistogram[i] = m_histogram[i].load(std::memory_order_relaxed);
  }
  statistics.wakeUps = m_wakeUps.load(std::memory_order_relaxed);
  statistics.lateWakeUps = m_lateWakeUps.load(std::memory_order_relaxed);
  statistics.maxWakeLatencyNanoseconds = m_maxWakeLatency.load(std::memory_order_relaxed);
  for (int i = 0; i < LoopStatistics::kWakeBins; ++i)
  {
    statistics.wakeLatencyHistogram[i] = m_wakeHistogram[i].load(std::memory_order_relaxed);
  }
  return statistics;
}

} // namespace proxima
