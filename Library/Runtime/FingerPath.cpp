#include "Runtime/FingerPath.h"

namespace proxima
{

Vec3 FingerPath::positionAt(double time, std::size_t& hint) const
{
  if (times.empty())
  {
    return Vec3{};
  }
  if (hint >= times.size() || times[hint] > time)
  {
    hint = 0;
  }
  while (hint + 1 < times.size() && times[hint + 1] <= time)
  {
    ++hint;
  }
  if (hint + 1 >= times.size() || time <= times[hint])
  {
    return positions[hint];
  }
  const double span = times[hint + 1] - times[hint];
  const double s = span > 0.0 ? (time - times[hint]) / span : 1.0;
  return positions[hint] + (positions[hint + 1] - positions[hint]) * s;
}

} // namespace proxima
