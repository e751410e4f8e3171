// How every program (proxima and its subcommands, proxima-inspector, proxima-trainer) words a
// usage error: one line, "PROGRAM: PROBLEM (see PROGRAM --help)". An unknown option or command is
// named, as the user typed it, with the nearest valid one, as git does ("unknown option
// '--raduis'; did you mean '--radius'?"), instead of CLI11's "The following arguments were not
// expected: 0.002 --raduis" (its words in reverse order) or "A subcommand is required"; a
// repeated option is said plainly instead of "At Most 1 required but received 2". Header only,
// with CLI11 only: the proxima front links no library of the toolkit.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstddef>
#include <regex>
#include <string>
#include <vector>

namespace proxima::cli
{

/// The edit distance between `a` and `b` counting a swap of two neighbours as one edit (the
/// optimal string alignment distance): "raduis" is 1 from "radius", "rnu" 1 from "run".
inline std::size_t editDistance(const std::string& a, const std::string& b)
{
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i)
  {
    d[i][0] = i;
  }
  for (std::size_t j = 0; j <= m; ++j)
  {
    d[0][j] = j;
  }
  for (std::size_t i = 1; i <= n; ++i)
  {
    for (std::size_t j = 1; j <= m; ++j)
    {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
      {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

/// The candidate nearest `word`, or empty when none is near enough to be what was meant: at most
/// a third of the word's letters apart (and at least one), or the word a prefix of exactly one
/// candidate. Ties go to the first candidate.
inline std::string nearestWord(const std::string& word, const std::vector<std::string>& candidates)
{
  std::string nearest;
  std::size_t best = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& candidate : candidates)
  {
    const std::size_t distance = editDistance(word, candidate);
    if (distance < best)
    {
      best = distance;
      nearest = candidate;
    }
  }
  if (nearest.empty() && word.size() >= 2)
  {
    std::size_t prefixed = 0;
    for (const std::string& candidate : candidates)
    {
      if (candidate.compare(0, word.size(), word) == 0)
      {
        ++prefixed;
        nearest = candidate;
      }
    }
    if (prefixed != 1)
    {
      nearest.clear();
    }
  }
  return nearest;
}

namespace detail
{
/// The chain of apps given on the command line: `app`, then each parsed subcommand in turn.
inline std::vector<const CLI::App*> parsedChain(const CLI::App& app)
{
  std::vector<const CLI::App*> chain{&app};
  for (;;)
  {
    const std::vector<CLI::App*> parsed = chain.back()->get_subcommands();
    if (parsed.empty())
    {
      return chain;
    }
    chain.push_back(parsed.front());
  }
}

/// Every option name of the apps in `chain`, as typed: "--radius", "-h".
inline std::vector<std::string> optionNames(const std::vector<const CLI::App*>& chain)
{
  std::vector<std::string> names;
  for (const CLI::App* app : chain)
  {
    for (const CLI::Option* option : app->get_options())
    {
      for (const std::string& name : option->get_lnames())
      {
        names.push_back("--" + name);
      }
      for (const std::string& name : option->get_snames())
      {
        names.push_back("-" + name);
      }
    }
  }
  return names;
}

/// The names of `app`'s subcommands.
inline std::vector<std::string> commandNames(const CLI::App& app)
{
  std::vector<std::string> names;
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
  {
    if (!command->get_name().empty())
    {
      names.push_back(command->get_name());
    }
  }
  return names;
}

/// "unknown KIND 'WORD'", and "; did you mean 'NEAREST'?" when one is near.
inline std::string unknown(const char* kind, const std::string& word,
                           const std::vector<std::string>& candidates)
{
  std::string text = std::string("unknown ") + kind + " '" + word + "'";
  const std::string nearest = nearestWord(word, candidates);
  if (!nearest.empty())
  {
    text += "; did you mean '" + nearest + "'?";
  }
  return text;
}

/// A word the command line did not take, said as what it most likely is.
inline std::string unexpected(const std::vector<const CLI::App*>& chain, const std::string& word)
{
  if (word.size() > 1 && word.front() == '-' && (word[1] < '0' || word[1] > '9') && word[1] != '.')
  {
    // "--raduis=0.002" is the option "--raduis".
    return unknown("option", word.substr(0, word.find('=')), optionNames(chain));
  }
  const std::vector<std::string> commands = commandNames(*chain.back());
  if (!commands.empty())
  {
    return unknown("command", word, commands);
  }
  return "unexpected argument '" + word + "' (no option takes it here)";
}
} // namespace detail

/// The one-line text of CLI11's usage error `error`, raised while parsing `app` (the top app).
inline std::string usageErrorText(const CLI::App& app, const CLI::Error& error)
{
  const std::vector<const CLI::App*> chain = detail::parsedChain(app);
  const std::vector<std::string> left = app.remaining(true);
  if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr && !left.empty())
  {
    return detail::unexpected(chain, left.front());
  }
  // A command line whose command is misspelled has no command, and the word is left over.
  if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr &&
      chain.back()->get_require_subcommand_min() > 0)
  {
    for (const std::string& word : left)
    {
      if (!word.empty() && word.front() != '-')
      {
        return detail::unknown("command", word, detail::commandNames(*chain.back()));
      }
    }
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr)
  {
    static const std::regex atMost("^(.*): At Most ([0-9]+) required but received ([0-9]+)$");
    std::smatch match;
    const std::string what = error.what();
    if (std::regex_match(what, match, atMost))
    {
      const unsigned long each = std::stoul(match[2]);
      const unsigned long received = std::stoul(match[3]);
      if (each > 0 && received % each == 0 && received / each > 1)
      {
        return match[1].str() + ": given " + std::to_string(received / each) +
               " times; give it once";
      }
    }
  }
  return error.what();
}

/// Words `app`'s usage errors as usageErrorText does, in one line that begins with `program`.
inline void configureUsageErrors(CLI::App& app, const std::string& program)
{
  app.failure_message([program](const CLI::App* top, const CLI::Error& error) {
    return program + ": " + usageErrorText(*top, error) + " (see " + program + " --help)\n";
  });
}

} // namespace proxima::cli
