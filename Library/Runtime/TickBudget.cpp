#include "Runtime/TickBudget.h"

#include <cstdio>

namespace proxima
{

std::string TickWorkBudget::text() const
{
  if (none())
  {
    return "none";
  }
  std::string spelled;
  if (seconds > 0.0)
  {
    // %g of microseconds: "50us", "12.5us", as they were given.
    char microseconds[64];
    std::snprintf(microseconds, sizeof microseconds, "%gus", seconds * 1e6);
    spelled = microseconds;
  }
  if (iterations > 0)
  {
    if (!spelled.empty())
    {
      spelled += ',';
    }
    spelled += std::to_string(iterations);
    spelled += "it";
  }
  return spelled;
}

} // namespace proxima
