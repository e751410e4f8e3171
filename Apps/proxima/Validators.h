// Number checks for command-line options with one-line messages (CLI11's own range validators
// print the whole range of double).
#pragma once

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "Runtime/TickBudget.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace proxima::cli
{

/// Reads `text` as a plain decimal number: an optional sign, digits with at most one point, an
/// optional exponent. Hexadecimal (`0x10` read as 16), `inf`, `nan` and trailing characters are
/// refused. False when `text` is not one, or its value overflows.
inline bool parsePlainNumber(const std::string& text, double& value)
{
  if (text.empty() || text.find_first_not_of("0123456789.eE+-") != std::string::npos ||
      text.find_first_of("0123456789") == std::string::npos)
  {
    return false;
  }
  const char* begin = text.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  return end == begin + text.size() && std::isfinite(value);
}

/// A number in `range` (ParameterRanges.h), with a message that names the range in short
/// numbers, not CLI11's 309-digit DBL_MAX.
inline CLI::Validator numberIn(const ParameterRange& range)
{
  return CLI::Validator(
    [range](std::string& input) -> std::string {
      double value = 0.0;
      if (!parsePlainNumber(input, value))
      {
        return "not a finite decimal number: " + input;
      }
      if (!range.contains(value))
      {
        return "must be " + describeRange(range) + ", not " + input;
      }
      return {};
    },
    "NUMBER");
}

/// A finite number > 0 (`strictlyPositive`) or >= 0, with no upper bound of its own.
inline CLI::Validator finiteNumber(bool strictlyPositive)
{
  return numberIn(ParameterRange{0.0, strictlyPositive, std::numeric_limits<double>::max(), ""});
}

/// A whole number of ticks: --max-ticks.
inline CLI::Validator tickCount()
{
  return CLI::Validator(
    [](std::string& input) -> std::string {
      double value = 0.0;
      if (!parsePlainNumber(input, value) || value < 1.0 || value != std::floor(value) ||
          value > 1e15)
      {
        return "must be a whole number of ticks from 1 to 1e15, not " + input;
      }
      return {};
    },
    "TICKS");
}

/// Refuses a run or path of more than `maxTicks` ticks before it writes anything, in words
/// that say how long it would be and how to go past the limit.
inline void checkTickCount(double ticks, double rate, double maxTicks, const std::string& what)
{
  if (ticks > maxTicks)
  {
    throw InputError("--max-ticks", what + " is " + shortNumber(ticks) + " ticks at " +
                                      shortNumber(rate) + " Hz, more than the limit of " +
                                      shortNumber(maxTicks) + " (give --max-ticks to go past it)");
  }
}

/// The largest --tick-budget terms taken: a proxy tick of more than a second, or of more than a
/// million iterations, is a typo, not a budget.
inline constexpr double kMaxTickBudgetMicroseconds = 1e6;
inline constexpr long kMaxTickBudgetIterations = 1000000;

/// Parses a --tick-budget value: `none`, or one or two comma-separated terms `<N>us` (microseconds
/// of wall time, N > 0, fractions allowed) and `<N>it` (move/update iterations, a whole N > 0),
/// each at most once: `50us`, `40it`, `50us,40it`. Returns why `text` is refused, empty when it
/// is taken (and `budget` holds it).
inline std::string parseTickBudget(const std::string& text, TickWorkBudget& budget)
{
  budget = TickWorkBudget{};
  if (text == "none")
  {
    return {};
  }
  const std::string usage = " (give <N>us, <N>it, both as <N>us,<N>it, or none)";
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

/// The CLI11 check of parseTickBudget.
inline CLI::Validator tickBudgetValue()
{
  return CLI::Validator(
    [](std::string& input) -> std::string {
      TickWorkBudget ignored;
      return parseTickBudget(input, ignored);
    },
    "BUDGET");
}

} // namespace proxima::cli
