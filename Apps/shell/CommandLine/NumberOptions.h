// Number checks for the command-line options of every program (proxima and its subcommands,
// proxima-inspector, proxima-trainer), with one-line messages that name the range in short
// numbers (CLI11's own range validators print the whole range of double), and help that shows
// the same range the check uses: both come from one ParameterRange, most of them from the table
// in IO/InputChecks/ParameterRanges.h. Header only, as CLI11 is.
#pragma once

#include "IO/InputChecks/ParameterRanges.h"

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

/// The range as --help shows it after the option's type: "FLOAT:above 0 and at most 1 m".
inline std::string rangeHelp(const ParameterRange& range)
{
  if (range.high == std::numeric_limits<double>::max())
  {
    return range.lowExcluded ? "above " + shortNumber(range.low) + range.unit
                             : "from " + shortNumber(range.low) + range.unit;
  }
  return describeRange(range);
}

/// A number in `range`, with a message that names the range in short numbers; --help shows the
/// range.
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
        return "must be " + rangeHelp(range) + ", not " + input;
      }
      return {};
    },
    rangeHelp(range));
}

/// A whole number in `range` (digits only: no sign, point or exponent), for counts and sizes.
inline CLI::Validator wholeNumberIn(const ParameterRange& range)
{
  const std::string words = "a whole number " + rangeHelp(range);
  return CLI::Validator(
    [range, words](std::string& input) -> std::string {
      if (input.empty() || input.size() > 15 ||
          input.find_first_not_of("0123456789") != std::string::npos)
      {
        return "must be " + words + ", not " + input;
      }
      if (!range.contains(std::strtod(input.c_str(), nullptr)))
      {
        return "must be " + words + ", not " + input;
      }
      return {};
    },
    words);
}

/// A finite number > 0 (`strictlyPositive`) or >= 0, with no upper bound of its own.
inline CLI::Validator finiteNumber(bool strictlyPositive)
{
  return numberIn(ParameterRange{0.0, strictlyPositive, std::numeric_limits<double>::max(), ""});
}

} // namespace proxima::cli
