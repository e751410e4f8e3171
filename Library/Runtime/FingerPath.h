// A scripted finger path: positions at increasing times, played back by linear interpolation at
// the servo rate (DESIGN.md section 3: rows may be sparser than the servo ticks).
#pragma once

#include "Core/Vec3.h"

#include <cstddef>
#include <vector>

namespace proxima
{

/// A finger path as rows of (time, position): `times[i]` goes with `positions[i]`, and the two
/// vectors always have the same length.
struct FingerPath
{
  /// Row times in seconds, non-decreasing.
  std::vector<double> times;
  /// Finger positions in metres, scene frame, one per row.
  std::vector<Vec3> positions;

  /// Number of rows.
  std::size_t size() const { return times.size(); }
  /// True when the path has no rows.
  bool empty() const { return times.empty(); }
  /// Time of the first row (s); the path must not be empty.
  double startTime() const { return times.front(); }
  /// Time of the last row (s); the path must not be empty.
  double endTime() const { return times.back(); }
  /// Adds a row at the end; `time` must not be before the last row's.
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
