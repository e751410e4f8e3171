// Number checks for command-line options with one-line messages: the shared ones of every
// program (NumberOptions.h), and the command line's own (ticks, tick budgets).
#pragma once

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "NumberOptions.h"
#include "Runtime/TickBudget.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace proxima::cli
{

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
