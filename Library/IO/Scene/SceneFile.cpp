#include "IO/Scene/SceneFile.h"

#include "IO/InputChecks/ParameterRanges.h"
#include "IO/JsonInput/JsonChecker.h"

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
using Json = CheckedJson;
using Keys = JsonChecker::Keys;

// Checks the document against the format of Documentation/SceneFiles.md and fills in the
// description. Every defect ends here, in fail(), as one InputError naming where it is.
class SceneReader : public JsonChecker
{
public:
  explicit SceneReader(const std::string& path)
    : JsonChecker(path)
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
      const double given = version->is_number() ? version->get<double>() : 0.0;
      if (!version->is_number() || !(given >= 1.0 && given <= kSceneFileVersion) ||
          given != std::floor(given))
      {
        fail("version", "must be 1, 2 or " + std::to_string(kSceneFileVersion) +
                          " (the scene file versions this program reads), got " + quoted(*version));
      }
      scene.version = static_cast<int>(version->get<double>());
    }
    m_version = scene.version;
    checkKeys(root, "", {"version", "gravity", "mjcf", "objects"});
    if (const Json* mjcf = find(root, "mjcf"))
    {
      needsVersion2("mjcf");
      if (find(root, "gravity") != nullptr)
      {
        fail("gravity", "a scene with an \"mjcf\" file takes gravity from the file's <option>");
      }
      scene.mjcf = filePath(*mjcf, "mjcf");
      m_mjcf = true;
    }
    if (const Json* gravity = find(root, "gravity"))
    {
      needsVersion2("gravity");
      const std::vector<double> g = numbers(*gravity, "gravity", 3, "[gx, gy, gz] in m/s^2");
      for (const double component : g)
      {
        if (!kGravityRange.contains(component))
        {
          fail("gravity", "each component must be " + describeRange(kGravityRange) + ", got " +
                            quoted(*gravity));
        }
      }
      scene.gravity = {g[0], g[1], g[2]};
    }
    const Json& objects = require(root, "objects", "");
    if (!objects.is_array() || objects.empty())
    {
      fail("objects", "must be an array of at least one object, got " + quoted(objects));
    }
    for (std::size_t i = 0; i < objects.size(); ++i)
    {
      scene.objects.push_back(readObject(objects[i], element("objects", i)));
    }
    if (scene.hasBodies() && scene.hasTissue())
    {
      // The runners step one dynamics per scene: the lever of a scene with a kidney beside it
      // stood still under the finger's press.
      for (std::size_t i = 0; i < scene.objects.size(); ++i)
      {
        if (scene.objects[i].hasTissue)
        {
          fail(child(element("objects", i), "tissue"),
               "a scene has bodies or tissue, not both yet (this one has bodies too): no "
               "runner steps rigid bodies and elastic solids together");
        }
      }
    }
    if (m_mjcf && !scene.hasBodies())
    {
      fail("mjcf", "no object binds a body of it (give an object \"body\": {\"name\": ...})");
    }
    return scene;
  }

private:
  SceneObject readObject(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"mesh", "scale", "pose", "material", "body", "tissue"});
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
    if (const Json* body = find(value, "body"))
    {
      needsVersion2(child(where, "body"));
      object.hasBody = true;
      object.body = readBody(*body, child(where, "body"));
    }
    if (const Json* tissue = find(value, "tissue"))
    {
      const std::string at = child(where, "tissue");
      if (m_version < 3)
      {
        fail(at, "tissue needs \"version\": 3 at the top level (this file reads as version " +
                   std::to_string(m_version) + ")");
      }
      if (object.hasBody)
      {
        fail(at, "an object is either a rigid body or tissue, not both");
      }
      // The tissue's surface is remade from its tetrahedra at every step: it has no point
      // normals to shade with, nor texture coordinates.
      if (object.material.shading == SceneShading::On)
      {
        fail(child(child(where, "material"), "shading"),
             "tissue is not shaded (its surface is remade from the tetrahedra)");
      }
      if (!object.material.textures.empty())
      {
        fail(child(child(where, "material"), "textures"),
             "tissue takes no texture maps (its surface has no texture coordinates)");
      }
      object.hasTissue = true;
      object.tissue = readTissue(*tissue, at);
    }
    return object;
  }

  SceneTissue readTissue(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where,
              {"youngs_modulus", "poisson_ratio", "density", "damping", "tet_size", "tets", "fixed",
               "inclusions"});
    SceneTissue tissue;
    tissue.youngsModulus = ranged(require(value, "youngs_modulus", where),
                                  child(where, "youngs_modulus"), kYoungsModulusRange);
    if (const Json* nu = find(value, "poisson_ratio"))
    {
      tissue.poissonRatio = ranged(*nu, child(where, "poisson_ratio"), kPoissonRatioRange);
    }
    if (const Json* density = find(value, "density"))
    {
      tissue.density = ranged(*density, child(where, "density"), kTissueDensityRange);
    }
    if (const Json* damping = find(value, "damping"))
    {
      tissue.damping = ranged(*damping, child(where, "damping"), kTissueDampingRange);
    }
    const Json* size = find(value, "tet_size");
    const Json* tets = find(value, "tets");
    if ((size == nullptr) == (tets == nullptr))
    {
      fail(where, std::string(size == nullptr ? "needs" : "takes only") +
                    " one of \"tet_size\" (m: the mesh is wrapped and filled) and \"tets\" (a "
                    ".vtu file of tetrahedra)");
    }
    if (size != nullptr)
    {
      tissue.tetSize = ranged(*size, child(where, "tet_size"), kTetSizeRange);
    }
    else
    {
      tissue.tets = filePath(*tets, child(where, "tets"));
    }
    // A solid held nowhere drifts away under the finger: the organ's attachment is required.
    const std::string fixedAt = child(where, "fixed");
    const Json& fixed = require(value, "fixed", where);
    requireObject(fixed, fixedAt);
    checkKeys(fixed, fixedAt, {"box"});
    const std::string boxAt = child(fixedAt, "box");
    const Json& box = require(fixed, "box", fixedAt);
    if (!box.is_array() || box.size() != 2)
    {
      fail(boxAt, "must be [[x0, y0, z0], [x1, y1, z1]] in metres, got " + quoted(box));
    }
    const std::vector<double> low = numbers(box[0], element(boxAt, 0), 3, "[x0, y0, z0] in metres");
    const std::vector<double> high =
      numbers(box[1], element(boxAt, 1), 3, "[x1, y1, z1] in metres");
    for (int axis = 0; axis < 3; ++axis)
    {
      if (!(low[axis] <= high[axis]))
      {
        fail(boxAt, "the first corner must be below the second on every axis, got " + quoted(box));
      }
    }
    tissue.fixedLow = {low[0], low[1], low[2]};
    tissue.fixedHigh = {high[0], high[1], high[2]};
    if (const Json* inclusions = find(value, "inclusions"))
    {
      const std::string at = child(where, "inclusions");
      if (!inclusions->is_array())
      {
        fail(at, "must be an array of inclusions [{\"center\": [x, y, z], \"radius\": r, "
                 "\"youngs_modulus\": E}], got " +
                   quoted(*inclusions));
      }
      for (std::size_t i = 0; i < inclusions->size(); ++i)
      {
        tissue.inclusions.push_back(readInclusion((*inclusions)[i], element(at, i)));
      }
    }
    return tissue;
  }

  SceneInclusion readInclusion(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"center", "radius", "youngs_modulus"});
    SceneInclusion inclusion;
    const std::vector<double> c =
      numbers(require(value, "center", where), child(where, "center"), 3, "[x, y, z] in metres");
    inclusion.center = {c[0], c[1], c[2]};
    inclusion.radius =
      ranged(require(value, "radius", where), child(where, "radius"), kStiffnessRegionRadiusRange);
    inclusion.youngsModulus = ranged(require(value, "youngs_modulus", where),
                                     child(where, "youngs_modulus"), kYoungsModulusRange);
    return inclusion;
  }

  void needsVersion2(const std::string& where) const
  {
    if (m_version < 2)
    {
      fail(where, "bodies need \"version\": 2 at the top level (this file reads as version 1)");
    }
  }

  void readJoint(const Json& value, const std::string& where, SceneBody& body) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"type", "axis", "anchor", "range", "stiffness", "damping"});
    const Json& type = require(value, "type", where);
    const std::string typeName = type.is_string() ? type.get<std::string>() : std::string();
    if (typeName == "hinge")
    {
      body.joint = SceneJoint::Hinge;
    }
    else if (typeName == "slide")
    {
      body.joint = SceneJoint::Slide;
    }
    else if (typeName == "ball")
    {
      body.joint = SceneJoint::Ball;
    }
    else if (typeName == "free")
    {
      body.joint = SceneJoint::Free;
    }
    else
    {
      fail(child(where, "type"),
           "must be \"hinge\", \"slide\", \"ball\" or \"free\", got " + quoted(type));
    }
    const bool axial = body.joint == SceneJoint::Hinge || body.joint == SceneJoint::Slide;
    const auto onlyFor = [&](const char* key, bool allowed, const char* why) {
      if (!allowed && find(value, key) != nullptr)
      {
        fail(child(where, key), "a " + typeName + " joint takes no " + key + " (" + why + ")");
      }
    };
    onlyFor("axis", axial, "only hinge and slide joints have an axis");
    onlyFor("range", axial, "only hinge and slide joints have one coordinate to limit");
    onlyFor("stiffness", body.joint != SceneJoint::Free, "a free body has no joint to spring");
    onlyFor("damping", body.joint != SceneJoint::Free, "a free body has no joint to damp");
    onlyFor("anchor", body.joint != SceneJoint::Free, "a free body turns about its centre of mass");
    if (axial)
    {
      const std::string at = child(where, "axis");
      const std::vector<double> a = numbers(require(value, "axis", where), at, 3, "[ax, ay, az]");
      // A direction of any length: scaled by its largest component first, so that neither
      // [1e300, 1e300, 0] (whose squared norm overflows) nor [1e-300, 0, 0] (whose squared norm
      // underflows) loses its direction.
      const Vec3 given{a[0], a[1], a[2]};
      if (!(maxAbsComponent(given) > 0.0))
      {
        fail(at, "must not be zero");
      }
      body.axis = overflowSafeDirection(given);
    }
    if (const Json* anchor = find(value, "anchor"))
    {
      const std::vector<double> a =
        numbers(*anchor, child(where, "anchor"), 3, "[x, y, z] in metres");
      body.anchor = {a[0], a[1], a[2]};
    }
    if (const Json* range = find(value, "range"))
    {
      const std::string at = child(where, "range");
      const std::vector<double> r = numbers(*range, at, 2, "[low, high]");
      if (!(r[0] < r[1]))
      {
        fail(at, "must be [low, high] with low below high, got " + quoted(*range));
      }
      body.limited = true;
      body.range[0] = r[0];
      body.range[1] = r[1];
    }
    if (const Json* stiffness = find(value, "stiffness"))
    {
      body.stiffness = ranged(*stiffness, child(where, "stiffness"), kJointStiffnessRange);
    }
    if (const Json* damping = find(value, "damping"))
    {
      body.damping = ranged(*damping, child(where, "damping"), kJointDampingRange);
    }
  }

  SceneBody readBody(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    SceneBody body;
    if (m_mjcf)
    {
      // Bound by name: the joint and the mass are the MJCF file's.
      for (const char* declared : {"joint", "density", "mass"})
      {
        if (find(value, declared) != nullptr)
        {
          fail(child(where, declared), "the scene's \"mjcf\" file gives the joints and masses: "
                                       "bind the object to one of its bodies by \"name\" alone");
        }
      }
      checkKeys(value, where, {"name"});
      const Json& name = require(value, "name", where);
      if (!name.is_string() || name.get<std::string>().empty())
      {
        fail(child(where, "name"),
             "must name a body of the scene's \"mjcf\" file, got " + quoted(name));
      }
      body.mjcfBody = name.get<std::string>();
      return body;
    }
    if (find(value, "name") != nullptr)
    {
      fail(child(where, "name"),
           "binds a body of an MJCF file, and the scene names none (give \"mjcf\" at the top "
           "level, or declare the body's \"joint\" here)");
    }
    checkKeys(value, where, {"joint", "density", "mass"});
    readJoint(require(value, "joint", where), child(where, "joint"), body);
    const Json* density = find(value, "density");
    const Json* mass = find(value, "mass");
    if ((density == nullptr) == (mass == nullptr))
    {
      fail(where, std::string(density == nullptr ? "needs" : "takes only") +
                    " one of \"density\" (kg/m^3) and \"mass\" (kg)");
    }
    if (density != nullptr)
    {
      body.density = ranged(*density, child(where, "density"), kBodyDensityRange);
    }
    else
    {
      body.mass = ranged(*mass, child(where, "mass"), kBodyMassRange);
    }
    return body;
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
      if (!(maxAbsComponent(axis) > 0.0))
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

  StiffnessRegion readStiffnessRegion(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"center", "radius", "scale"});
    StiffnessRegion region;
    const std::vector<double> c =
      numbers(require(value, "center", where), child(where, "center"), 3, "[x, y, z] in metres");
    region.center = {c[0], c[1], c[2]};
    region.radius =
      ranged(require(value, "radius", where), child(where, "radius"), kStiffnessRegionRadiusRange);
    region.scale =
      ranged(require(value, "scale", where), child(where, "scale"), kStiffnessScaleRange);
    return region;
  }

  SceneMaterial readMaterial(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where,
              {"shading", "feature_angle_deg", "static_friction", "dynamic_friction", "viscosity",
               "stiffness", "stiffness_regions", "textures"});
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
    if (const Json* k = find(value, "stiffness"))
    {
      material.stiffness = ranged(*k, child(where, "stiffness"), kStiffnessScaleRange);
    }
    if (const Json* regions = find(value, "stiffness_regions"))
    {
      const std::string at = child(where, "stiffness_regions");
      if (!regions->is_array())
      {
        fail(at, "must be an array of regions [{\"center\": [x, y, z], \"radius\": r, "
                 "\"scale\": s}], got " +
                   quoted(*regions));
      }
      for (std::size_t i = 0; i < regions->size(); ++i)
      {
        material.stiffnessRegions.push_back(readStiffnessRegion((*regions)[i], element(at, i)));
      }
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
  int m_version = 1;
  /// The scene names an MJCF file: bodies bind its bodies by name.
  bool m_mjcf = false;
};
} // namespace

SceneDescription readSceneFile(const std::string& path)
{
  return SceneReader(path).read(readCheckedJsonFile(path, "scene file"));
}

} // namespace proxima
