// The chain of straight segments one ProxySolver::update moved the proxy along, recorded on
// request (ProxySolver::recordMoves) so that an oracle can check every segment the proxy swept,
// not only where the tick ended. Off by default: a solver without a record pays one null test per
// move.
#pragma once

#include "Core/Vec3.h"

#include <cstddef>
#include <vector>

namespace proxima
{

/// What a recorded point is to the tick's approach to the finger.
enum class MovePointKind : unsigned char
{
  /// The tick's start, the end of a move that ended no farther from the finger than
  /// the accepted point before it, or the end of a retrace back to that point: the finger distance
  /// at these points never increases along the tick.
  Accepted,
  /// The end of a move that left the finger (a curvature-stretched slide overshoots on purpose,
  /// and the moves after it usually win the distance back), or a point the retrace walks back
  /// over. Swept clear like every segment, but exempt from the approach.
  Trial,
};

/// One recorded point of the proxy's path through a tick.
struct MovePoint
{
  /// Where the proxy's centre was (m), in the scene's frame.
  Vec3 position;
  /// Whether the point counts for the tick's approach to the finger.
  MovePointKind kind = MovePointKind::Accepted;
};

/// Filled by ProxySolver::update when given to recordMoves: points[0] is where the tick began, and
/// each segment points[k-1] -> points[k] was swept clear. The caller sizes `points` (the solver
/// never allocates); points past its size are dropped and `overflowed` is set.
struct MoveRecord
{
  /// A record with room for `capacity` points, allocated here.
  explicit MoveRecord(std::size_t capacity = 4096)
    : points(capacity)
  {}

  /// The storage: its size is the capacity, and only the first `count` points are recorded.
  std::vector<MovePoint> points;
  /// Number of points recorded, at most points.size().
  std::size_t count = 0;
  /// True when a point did not fit and was dropped.
  bool overflowed = false;

  /// Empties the record for a new tick; keeps its storage.
  void clear()
  {
    count = 0;
    overflowed = false;
  }
  /// Records a point, or sets `overflowed` when the storage is full. Never allocates.
  void add(const Vec3& position, MovePointKind kind)
  {
    if (count < points.size())
    {
      points[count++] = MovePoint{position, kind};
    }
    else
    {
      overflowed = true;
    }
  }
  /// Marks the last point recorded as a trial (the solver judges a move after recording it).
  void markLastTrial()
  {
    if (count > 0)
    {
      points[count - 1].kind = MovePointKind::Trial;
    }
  }
};

} // namespace proxima
