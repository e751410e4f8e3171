// A scripted finger path: positions at increasing times, played back by linear interpolation at
// the servo rate (DESIGN.md section 3: rows may be sparser than the servo ticks).
#pragma once

#include "Core/Vec3.h"

#include <cstddef>
#include <vector>

namespace proxima
{

struct FingerPath
{
  std::vector<double> times;
  std::vector<Vec3> positions;

  std::size_t size() const { return times.size(); }
  bool empty() const { return times.empty(); }
  double startTime() const { return times.front(); }
  double endTime() const { return times.back(); }
  void append(double time, const Vec3& position)
  {
    times.push_back(time);
    positions.push_back(position);
  }

  /// Position at `time`, interpolated linearly between rows and held beyond the ends. `hint` is
  /// the row to start looking from (pass the previous answer back for O(1) playback).
  Vec3 positionAt(double time, std::size_t& hint) const;
};

} // namespace proxima
