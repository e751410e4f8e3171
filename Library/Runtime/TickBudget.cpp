#include "Runtime/TickBudget.h"

#include <cstdio>
#include <string>

namespace proxima
{

std::string TickWorkBudget::text() const
{
  if (none())
  {
    return "none";
  }
  if (isRealtimeDefault())
  {
    return "default";
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

std::string parseTickBudget(const std::string& text, TickWorkBudget& budget)
{
  budget = TickWorkBudget{};
  if (text == "none")
  {
    return {};
  }
  if (text == "default")
  {
    budget = TickWorkBudget::realtimeDefault();
    return {};
  }
  const std::string usage = " (give <N>us, <N>it, both as <N>us,<N>it, default or none)";
  if (text.empty())
  {
    return "empty" + usage;
  }
  bool haveSeconds = false;
  bool haveIterations = false;
  std::size_t begin = 0;
  while (begin <= text.size())
  {
    const std::size_t comma = text.find(',', begin);
    const std::size_t end = comma == std::string::npos ? text.size() : comma;
    const std::string term = text.substr(begin, end - begin);
    const auto endsWith = [&term](const char* unit) {
      return term.size() > 2 && term.compare(term.size() - 2, 2, unit) == 0;
    };
    if (term.empty())
    {
      return "an empty term in '" + text + "'" + usage;
    }
    if (!endsWith("us") && !endsWith("it"))
    {
      return "'" + term + "': unknown or missing unit (us: microseconds, it: iterations)" + usage;
    }
    const bool microseconds = endsWith("us");
    const std::string number = term.substr(0, term.size() - 2);
    // Digits and at most one point only: no sign, exponent, hex, inf or nan reach stod.
    const bool plain = number.find_first_not_of("0123456789.") == std::string::npos &&
                       number.find_first_of("0123456789") != std::string::npos &&
                       number.find('.') == number.rfind('.');
    if (!plain)
    {
      return "'" + term + "' is not a positive number of " +
             (microseconds ? "microseconds" : "iterations") + usage;
    }
    if (microseconds)
    {
      const double value = std::stod(number);
      if (haveSeconds)
      {
        return "gives microseconds twice: " + text;
      }
      if (!(value > 0.0) || value > kMaxTickBudgetMicroseconds)
      {
        return "'" + term + "' must be above 0 and at most 1000000us (one second)";
      }
      haveSeconds = true;
      budget.seconds = value / 1e6; // divided, not times 1e-6: 50us gives exactly 5e-05
    }
    else
    {
      if (number.find('.') != std::string::npos)
      {
        return "'" + term + "' must be a whole number of iterations";
      }
      if (haveIterations)
      {
        return "gives iterations twice: " + text;
      }
      // Length first: stol would overflow on a long run of digits.
      const long value = number.size() > 7 ? kMaxTickBudgetIterations + 1 : std::stol(number);
      if (value < 1 || value > kMaxTickBudgetIterations)
      {
        return "'" + term + "' must be from 1it to 1000000it";
      }
      haveIterations = true;
      budget.iterations = static_cast<int>(value);
    }
    if (comma == std::string::npos)
    {
      break;
    }
    begin = comma + 1;
  }
  return {};
}

} // namespace proxima
