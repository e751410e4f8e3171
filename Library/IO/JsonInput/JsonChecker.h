// Checked JSON input files (scene files, exercise files): one reader for all, so that every JSON
// file Proxima reads refuses the same defects with the same words. A missing, unreadable or empty
// file, JSON that does not parse (with its line and column), a key given twice in one object, an
// unknown key (with the nearest known one suggested), a value of the wrong type or outside its
// range: each is one InputError naming the file and where in it (`objects[1].material.viscosity`).
#pragma once

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace proxima
{

/// Ordered, so that of two defects the one earlier in the file is reported.
using CheckedJson = nlohmann::ordered_json;

/// Reads and parses the JSON file `path`; `kind` names it in the message of a file that cannot be
/// read ("scene file").
CheckedJson readCheckedJsonFile(const std::string& path, const std::string& kind);

/// `text` cut to at most `longest` bytes with " ..." at the end when it is longer, never inside a
/// UTF-8 sequence (a message is printed whole on a terminal).
std::string cutShort(std::string text, std::size_t longest);

/// The checks a reader of one JSON file makes, each failing with one InputError naming the file
/// and the place. A reader derives from it and reads its format with these.
class JsonChecker
{
public:
  /// The JSON value the checks take: ordered, as the file wrote it.
  using Json = CheckedJson;
  /// A braced list of JSON spellings: the known keys of an object, or the names of a choice.
  using Keys = std::initializer_list<std::string_view>;

  /// `path` names the file in messages; relative file paths in it are resolved against its folder.
  explicit JsonChecker(const std::string& path)
    : m_path(path)
    , m_folder(std::filesystem::path(path).parent_path())
  {}

  /// The value as the file wrote it, cut short when long, for "got ..." in messages.
  static std::string quoted(const Json& value);
  /// `where` and a key below it: "objects[0]" and "mesh" give "objects[0].mesh".
  static std::string child(const std::string& where, std::string_view key)
  {
    return where.empty() ? std::string(key) : where + "." + std::string(key);
  }
  /// `where` and an array index below it: "objects" and 2 give "objects[2]".
  static std::string element(const std::string& where, std::size_t index)
  {
    return where + "[" + std::to_string(index) + "]";
  }
  /// The Levenshtein distance of `a` and `b`: the fewest single-character insertions,
  /// deletions and substitutions that turn one into the other.
  static std::size_t editDistance(std::string_view a, std::string_view b);

  /// Throws the InputError "<path>: <where>: <defect>" ("top level" for an empty `where`).
  [[noreturn]] void fail(const std::string& where, const std::string& defect) const
  {
    throw InputError(m_path, (where.empty() ? std::string("top level") : where) + ": " + defect);
  }

  /// Fails unless `value` is a JSON object.
  void requireObject(const Json& value, const std::string& where) const
  {
    if (!value.is_object())
    {
      fail(where, "must be a JSON object {...}, got " + quoted(value));
    }
  }

  /// Fails at the first key of `object` that is not in `known`, suggesting the nearest known key
  /// when it is a close misspelling (edit distance below 3), else listing them. Unknown keys are
  /// refused so that a misspelt optional key is not silently ignored.
  void checkKeys(const Json& object, const std::string& where, Keys known) const
  {
    for (auto it = object.begin(); it != object.end(); ++it)
    {
      const std::string& key = it.key();
      if (std::find(known.begin(), known.end(), key) != known.end())
      {
        continue;
      }
      std::string_view nearest;
      std::size_t nearestDistance = 3; // suggest only close misspellings
      std::string list;
      for (std::string_view candidate : known)
      {
        const std::size_t distance = editDistance(key, candidate);
        if (distance < nearestDistance)
        {
          nearest = candidate;
          nearestDistance = distance;
        }
        list += (list.empty() ? "" : ", ") + std::string(candidate);
      }
      fail(child(where, cutShort(key, 40)),
           nearest.empty() ? "unknown key (the keys here are " + list + ")"
                           : "unknown key (did you mean \"" + std::string(nearest) + "\"?)");
    }
  }

  /// The value of `key` in `object`, or nullptr if the key is absent.
  static const Json* find(const Json& object, std::string_view key)
  {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  /// The value of `key` in `object`; fails at `where` if the key is absent.
  const Json& require(const Json& object, std::string_view key, const std::string& where) const
  {
    const Json* value = find(object, key);
    if (value == nullptr)
    {
      fail(where, "missing the required key \"" + std::string(key) + "\"");
    }
    return *value;
  }

  /// A JSON number that `accept` takes; otherwise fails with "must be <rule>, got ...", `rule`
  /// worded for the message ("a number >= 0").
  template <typename Accept>
  double number(const Json& value, const std::string& where, const std::string& rule,
                Accept accept) const
  {
    // JSON numbers are finite here: the parser refuses NaN, infinity and overflow.
    if (!value.is_number() || !accept(value.get<double>()))
    {
      fail(where, "must be " + rule + ", got " + quoted(value));
    }
    return value.get<double>();
  }

  /// Any number; fails if `value` is not one.
  double number(const Json& value, const std::string& where) const
  {
    return number(value, where, "a number", [](double) { return true; });
  }

  /// A number in one of the ranges the command line shares (ParameterRanges.h); the message
  /// gives the range in words.
  double ranged(const Json& value, const std::string& where, const ParameterRange& range) const
  {
    return number(value, where, "a number " + describeRange(range),
                  [&range](double v) { return range.contains(v); });
  }

  /// A non-empty string naming a file: returned as written if absolute, else resolved against
  /// the folder of the JSON file.
  std::string filePath(const Json& value, const std::string& where) const
  {
    if (!value.is_string() || value.get<std::string>().empty())
    {
      fail(where, "must be a file path (a non-empty string), got " + quoted(value));
    }
    const std::filesystem::path written(value.get<std::string>());
    // Relative to the scene file, so that a scene and its meshes can move together.
    return written.is_absolute() || m_folder.empty() ? written.string()
                                                     : (m_folder / written).string();
  }

  /// One of `names` (the JSON spellings), as its index in `names`; fails listing them otherwise.
  std::size_t choice(const Json& value, const std::string& where, Keys names) const
  {
    if (value.is_string())
    {
      const auto it = std::find(names.begin(), names.end(), value.get<std::string>());
      if (it != names.end())
      {
        return static_cast<std::size_t>(it - names.begin());
      }
    }
    std::string list;
    std::size_t i = 0;
    for (std::string_view name : names)
    {
      list.append(i == 0 ? "" : (i + 1 == names.size() ? " or " : ", "));
      list.append("\"").append(name).append("\"");
      ++i;
    }
    fail(where, "must be " + list + ", got " + quoted(value));
  }

  /// An array of exactly `count` numbers; `meaning` describes them in the message
  /// ("[x, y, z] in metres").
  std::vector<double> numbers(const Json& value, const std::string& where, std::size_t count,
                              const std::string& meaning) const
  {
    if (!value.is_array() || value.size() != count)
    {
      fail(where, "must be an array of " + std::to_string(count) + " numbers " + meaning +
                    ", got " + quoted(value));
    }
    std::vector<double> result;
    for (std::size_t i = 0; i < count; ++i)
    {
      result.push_back(number(value[i], element(where, i)));
    }
    return result;
  }

  /// A non-empty string.
  std::string text(const Json& value, const std::string& where) const
  {
    if (!value.is_string() || value.get<std::string>().empty())
    {
      fail(where, "must be a non-empty string, got " + quoted(value));
    }
    return value.get<std::string>();
  }

protected:
  /// The file as the caller named it, for messages.
  std::string m_path;
  /// The file's folder, against which relative file paths resolve; empty for a bare file name.
  std::filesystem::path m_folder;
};

} // namespace proxima
