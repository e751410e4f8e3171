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
