#include "IO/Scene/SceneFile.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/InputChecks/ParameterRanges.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace proxima
{
namespace
{
namespace fs = std::filesystem;
// Ordered, so that of two defects the one earlier in the file is reported.
using Json = nlohmann::ordered_json;
using Keys = std::initializer_list<std::string_view>;

// `text` cut to at most `longest` bytes with " ..." at the end when it is longer, never inside a
// UTF-8 sequence (a message is printed whole on a terminal).
std::string cutShort(std::string text, std::size_t longest)
{
  if (text.size() <= longest)
  {
    return text;
  }
  std::size_t end = longest - 4;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0u) == 0x80u)
  {
    --end; // a continuation byte: back to the start of its character
  }
  text.resize(end);
  return text + " ...";
}

std::string readWholeFile(const std::string& path)
{
  detail::requireReadableFile(path, "scene file");
  std::ifstream stream(path, std::ios::binary);
  if (!stream)
  {
    throw InputError(path, std::string("cannot open the file (") + std::strerror(errno) + ")");
  }
  std::string text{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (stream.bad())
  {
    throw InputError(path, "cannot read the file");
  }
  if (text.empty())
  {
    throw InputError(path, "the file is empty");
  }
  return text;
}

// nlohmann keeps the last of two equal keys without a word, which would hide a pasted line that
// overrides an earlier one; the parser callback sees every key, so repeats are refused there.
// It also tracks where in the document each event is, to say so.
class RepeatedKeyCheck
{
public:
  explicit RepeatedKeyCheck(const std::string& path)
    : m_path(path)
  {}

  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed)
  {
    using Event = Json::parse_event_t;
    switch (event)
    {
      case Event::object_start:
      case Event::array_start:
      case Event::value:
        if (!m_frames.empty() && m_frames.back().array)
        {
          ++m_frames.back().index;
        }
        if (event != Event::value)
        {
          m_frames.push_back(Frame{event == Event::array_start, -1, {}, {}});
        }
        break;
      case Event::key:
      {
        Frame& frame = m_frames.back();
        frame.key = parsed.get<std::string>();
        if (!frame.keys.insert(frame.key).second)
        {
          throw InputError(m_path, location() + ": the key appears twice in the same object");
        }
        break;
      }
      case Event::object_end:
      case Event::array_end: m_frames.pop_back(); break;
    }
    return true;
  }

private:
  struct Frame
  {
    bool array = false;
    long index = -1;
    std::string key;
    std::set<std::string> keys;
  };

  std::string location() const
  {
    std::string where;
    for (const Frame& frame : m_frames)
    {
      if (frame.array)
      {
        where += "[" + std::to_string(frame.index) + "]";
      }
      else
      {
        // A key written by mistake can be of any length; the message stays readable.
        where += (where.empty() ? "" : ".") + cutShort(frame.key, 40);
      }
    }
    return where;
  }

  const std::string& m_path;
  std::vector<Frame> m_frames;
};

Json parseJson(const std::string& path, const std::string& text)
{
  try
  {
    return Json::parse(text, RepeatedKeyCheck(path));
  }
  catch (const nlohmann::json::exception& error)
  {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..." keeps
    // its position and reason, without the library's prefix.
    std::string reason = error.what();
    const std::size_t bracket = reason.find("] ");
    if (bracket != std::string::npos)
    {
      reason.erase(0, bracket + 2);
    }
    const std::string_view at = "parse error at ";
    if (reason.starts_with(at))
    {
      reason.erase(0, at.size());
    }
    // The reason quotes the offending token, which may be a whole line of digits or a string.
    throw InputError(path, "not valid JSON: " + cutShort(reason, 160));
  }
}

// Compact JSON of `value`, as dump() writes it, but stopping once `out` is longer than `limit`
// and at a nesting depth of kMaxQuotedDepth: dump() recurses once per level, and a file of a
// hundred thousand nested brackets (which the parser itself takes without recursion) would
// overflow the stack while the message about it is written.
constexpr int kMaxQuotedDepth = 8;

void appendQuoted(const Json& value, std::size_t limit, int depth, std::string& out)
{
  if (!value.is_structured())
  {
    out += value.dump();
    return;
  }
  if (depth == kMaxQuotedDepth)
  {
    out += "...";
    return;
  }
  const bool array = value.is_array();
  out += array ? '[' : '{';
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it)
  {
    if (out.size() > limit)
    {
      return;
    }
    if (!first)
    {
      out += ',';
    }
    first = false;
    if (!array)
    {
      out += Json(it.key()).dump();
      out += ':';
    }
    appendQuoted(*it, limit, depth + 1, out);
  }
  out += array ? ']' : '}';
}

// The value as the file wrote it, cut short when long, for "got ..." in messages.
std::string quoted(const Json& value)
{
  constexpr std::size_t kLongest = 40;
  std::string text;
  appendQuoted(value, kLongest, 0, text);
  return cutShort(std::move(text), kLongest);
}

std::size_t editDistance(std::string_view a, std::string_view b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
  {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string child(const std::string& where, std::string_view key)
{
  return where.empty() ? std::string(key) : where + "." + std::string(key);
}

std::string element(const std::string& where, std::size_t index)
{
  return where + "[" + std::to_string(index) + "]";
}

// Checks the document against the format of Documentation/SceneFiles.md and fills in the
// description. Every defect ends here, in fail(), as one InputError naming where it is.
class SceneReader
{
public:
  explicit SceneReader(const std::string& path)
    : m_path(path)
    , m_folder(fs::path(path).parent_path())
  {}

  SceneDescription read(const Json& root)
  {
    SceneDescription scene;
    scene.path = m_path;
    requireObject(root, "top level");
    // The version first: a newer file's new keys should be reported as a newer version, not as
    // unknown keys.
    if (const Json* version = find(root, "version"))
    {
      if (!version->is_number() || version->get<double>() != kSceneFileVersion)
      {
        fail("version", "must be " + std::to_string(kSceneFileVersion) +
                          " (the scene file version this program reads), got " + quoted(*version));
      }
      scene.version = kSceneFileVersion;
    }
    checkKeys(root, "", {"version", "objects"});
    const Json& objects = require(root, "objects", "");
    if (!objects.is_array() || objects.empty())
    {
      fail("objects", "must be an array of at least one object, got " + quoted(objects));
    }
    for (std::size_t i = 0; i < objects.size(); ++i)
    {
      scene.objects.push_back(readObject(objects[i], element("objects", i)));
    }
    return scene;
  }

private:
  [[noreturn]] void fail(const std::string& where, const std::string& defect) const
  {
    throw InputError(m_path, (where.empty() ? std::string("top level") : where) + ": " + defect);
  }

  void requireObject(const Json& value, const std::string& where) const
  {
    if (!value.is_object())
    {
      fail(where, "must be a JSON object {...}, got " + quoted(value));
    }
  }

  // Unknown keys are refused, so that a misspelt optional key is not silently ignored.
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

  static const Json* find(const Json& object, std::string_view key)
  {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  const Json& require(const Json& object, std::string_view key, const std::string& where) const
  {
    const Json* value = find(object, key);
    if (value == nullptr)
    {
      fail(where, "missing the required key \"" + std::string(key) + "\"");
    }
    return *value;
  }

  // A number checked against `rule` (worded for the message, "a number >= 0").
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

  double number(const Json& value, const std::string& where) const
  {
    return number(value, where, "a number", [](double) { return true; });
  }

  // A number in one of the ranges the command line shares (ParameterRanges.h).
  double ranged(const Json& value, const std::string& where, const ParameterRange& range) const
  {
    return number(value, where, "a number " + describeRange(range),
                  [&range](double v) { return range.contains(v); });
  }

  std::string filePath(const Json& value, const std::string& where) const
  {
    if (!value.is_string() || value.get<std::string>().empty())
    {
      fail(where, "must be a file path (a non-empty string), got " + quoted(value));
    }
    const fs::path written(value.get<std::string>());
    // Relative to the scene file, so that a scene and its meshes can move together.
    return written.is_absolute() || m_folder.empty() ? written.string()
                                                     : (m_folder / written).string();
  }

  // One of `names` (the JSON spellings), as its index.
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

  SceneObject readObject(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"mesh", "scale", "pose", "material"});
    SceneObject object;
    object.mesh = filePath(require(value, "mesh", where), child(where, "mesh"));
    if (const Json* scale = find(value, "scale"))
    {
      object.scale = ranged(*scale, child(where, "scale"), kMeshScaleRange);
    }
    if (const Json* pose = find(value, "pose"))
    {
      object.pose = readPose(*pose, child(where, "pose"));
    }
    if (const Json* material = find(value, "material"))
    {
      object.material = readMaterial(*material, child(where, "material"));
    }
    return object;
  }

  ScenePose readPose(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"translation", "rotation"});
    ScenePose pose;
    if (const Json* translation = find(value, "translation"))
    {
      const std::vector<double> t =
        numbers(*translation, child(where, "translation"), 3, "[x, y, z] in metres");
      pose.translation = {t[0], t[1], t[2]};
    }
    if (const Json* rotation = find(value, "rotation"))
    {
      pose.rotation = readRotation(*rotation, child(where, "rotation"));
    }
    return pose;
  }

  UnitQuaternion readRotation(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"axis_angle_deg", "quaternion"});
    const Json* axisAngle = find(value, "axis_angle_deg");
    const Json* quaternion = find(value, "quaternion");
    if ((axisAngle == nullptr) == (quaternion == nullptr))
    {
      fail(where, std::string(axisAngle == nullptr ? "needs" : "takes only") +
                    " one of \"axis_angle_deg\" and \"quaternion\"");
    }
    if (axisAngle != nullptr)
    {
      const std::string at = child(where, "axis_angle_deg");
      const std::vector<double> a = numbers(*axisAngle, at, 4, "[ax, ay, az, degrees]");
      const Vec3 axis{a[0], a[1], a[2]};
      if (!(norm(axis) > 0.0))
      {
        fail(at, "the axis (the first three numbers) must not be zero");
      }
      return UnitQuaternion::fromAxisAngle(axis, a[3]);
    }
    const std::string at = child(where, "quaternion");
    const std::vector<double> q = numbers(*quaternion, at, 4, "[w, x, y, z]");
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    // Rounded decimals (0.7071) are fine; a norm far from 1 is more likely a wrong order or a
    // mistyped component than a quaternion meant to be scaled.
    if (!(std::abs(length - 1.0) <= kQuaternionNormTolerance))
    {
      std::ostringstream defect;
      defect << "must be a unit quaternion [w, x, y, z] (norm within " << kQuaternionNormTolerance
             << " of 1), got norm " << length;
      fail(at, defect.str());
    }
    return UnitQuaternion::normalized(q[0], q[1], q[2], q[3]);
  }

  SceneMaterial readMaterial(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where,
              {"shading", "feature_angle_deg", "static_friction", "dynamic_friction", "viscosity",
               "textures"});
    SceneMaterial material;
    if (const Json* shading = find(value, "shading"))
    {
      constexpr SceneShading kModes[] = {SceneShading::Off, SceneShading::On, SceneShading::Auto};
      material.shading = kModes[choice(*shading, child(where, "shading"), {"off", "on", "auto"})];
    }
    if (const Json* angle = find(value, "feature_angle_deg"))
    {
      material.featureAngleDegrees =
        ranged(*angle, child(where, "feature_angle_deg"), kFeatureAngleRange);
    }
    if (const Json* mu = find(value, "static_friction"))
    {
      material.staticFriction = ranged(*mu, child(where, "static_friction"), kFrictionRange);
    }
    if (const Json* mu = find(value, "dynamic_friction"))
    {
      material.dynamicFriction = ranged(*mu, child(where, "dynamic_friction"), kFrictionRange);
    }
    if (const Json* b = find(value, "viscosity"))
    {
      material.viscosity = ranged(*b, child(where, "viscosity"), kViscosityRange);
    }
    const std::string friction =
      frictionPairError(material.staticFriction, material.dynamicFriction, "static_friction");
    if (!friction.empty())
    {
      fail(child(where, "dynamic_friction"), friction);
    }
    if (const Json* textures = find(value, "textures"))
    {
      const std::string at = child(where, "textures");
      if (!textures->is_array())
      {
        fail(at, "must be an array of texture maps [{...}], got " + quoted(*textures));
      }
      for (std::size_t i = 0; i < textures->size(); ++i)
      {
        material.textures.push_back(readTexture((*textures)[i], element(at, i), material));
      }
    }
    return material;
  }

  SceneTexture readTexture(const Json& value, const std::string& where,
                           const SceneMaterial& material) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"image", "role", "amplitude", "channel"});
    SceneTexture texture;
    texture.image = filePath(require(value, "image", where), child(where, "image"));
    constexpr TextureRole kRoles[] = {TextureRole::Bump, TextureRole::Friction,
                                      TextureRole::Viscosity, TextureRole::Stiffness};
    texture.role = kRoles[choice(require(value, "role", where), child(where, "role"),
                                 {"bump", "friction", "viscosity", "stiffness"})];
    const Json* amplitude = find(value, "amplitude");
    if (texture.role == TextureRole::Bump)
    {
      if (amplitude == nullptr)
      {
        fail(where, "missing the required key \"amplitude\" (metres of height per unit of image "
                    "value, for a bump map)");
      }
      texture.amplitude =
        number(*amplitude, child(where, "amplitude"), "a number other than 0 (metres)",
               [](double v) { return v != 0.0; });
    }
    else if (amplitude != nullptr)
    {
      const std::string role =
        texture.role == TextureRole::Friction
          ? "friction"
          : (texture.role == TextureRole::Viscosity ? "viscosity" : "stiffness");
      fail(child(where, "amplitude"),
           "is for bump maps only: a " + role +
             " map scales the material's coefficient by the image value");
    }
    // A property map scales a coefficient; on a coefficient of 0 it would do nothing, which is
    // more likely a misunderstanding (the map taken for the coefficient itself) than intended.
    if (texture.role == TextureRole::Friction && material.staticFriction == 0.0 &&
        material.dynamicFriction == 0.0)
    {
      fail(child(where, "role"), "a friction map scales static_friction and dynamic_friction, "
                                 "but the material sets neither above 0");
    }
    if (texture.role == TextureRole::Viscosity && material.viscosity == 0.0)
    {
      fail(child(where, "role"),
           "a viscosity map scales viscosity, but the material does not set it above 0");
    }
    if (const Json* channel = find(value, "channel"))
    {
      constexpr TextureChannel kChannels[] = {TextureChannel::Luminance, TextureChannel::Red,
                                              TextureChannel::Green, TextureChannel::Blue,
                                              TextureChannel::Alpha};
      texture.channel = kChannels[choice(*channel, child(where, "channel"),
                                         {"luminance", "red", "green", "blue", "alpha"})];
    }
    return texture;
  }

  static constexpr double kQuaternionNormTolerance = 1e-3;

  const std::string& m_path;
  fs::path m_folder;
};
} // namespace

SceneDescription readSceneFile(const std::string& path)
{
  const std::string text = readWholeFile(path);
  const Json root = parseJson(path, text);
  return SceneReader(path).read(root);
}

} // namespace proxima
