// Number checks for command-line options with one-line messages (CLI11's own range validators
// print the whole range of double).
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace proxima::cli
{

/// A finite number > 0 (`strictlyPositive`) or >= 0.
inline CLI::Validator finiteNumber(bool strictlyPositive)
{
  return CLI::Validator(
    [strictlyPositive](std::string& input) -> std::string {
      double value = 0.0;
      std::size_t used = 0;
      try
      {
        value = std::stod(input, &used);
      }
      catch (const std::exception&)
      {
        used = 0;
      }
      if (used != input.size() || !std::isfinite(value))
      {
        return "not a finite number: " + input;
      }
      if (strictlyPositive ? !(value > 0.0) : !(value >= 0.0))
      {
        return std::string("must be ") + (strictlyPositive ? "greater than 0" : "0 or more") +
               ", not " + input;
      }
      return {};
    },
    strictlyPositive ? "POSITIVE" : "NONNEGATIVE");
}

} // namespace proxima::cli
