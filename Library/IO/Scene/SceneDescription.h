// What a scene file says, checked but not yet loaded: the objects' mesh files, scales, poses and
// materials, with every path resolved against the scene file's folder. Plain data, no JSON: a
// program can also fill one in by hand and build it (IO/SceneBuilder.h). The file format is in
// Documentation/SceneFiles.md.
#pragma once

#include "IO/Scene/ScenePose.h"
#include "IO/Scene/TextureImageFile.h"
#include "Proxy/SurfaceMaterial.h"

#include <string>
#include <vector>

namespace proxima
{

/// How an object asks for force shading (Documentation/ForceShading.md).
enum class SceneShading
{
  /// Never shade.
  Off,
  /// Shade; a mesh whose file has no point normals gets them from withFeatureAngleNormals.
  On,
  /// Shade exactly when the mesh file has point normals.
  Auto
};

/// One texture map of a material: an image file and what it modulates (paper 4.3).
struct SceneTexture
{
  /// The image file, resolved against the scene file's folder.
  std::string image;
  TextureRole role = TextureRole::Bump;
  /// Bump maps: metres of height per unit of image value. Other roles: 0.
  double amplitude = 0.0;
  TextureChannel channel = TextureChannel::Luminance;
};

struct SceneMaterial
{
  SceneShading shading = SceneShading::Off;
  /// For shading On on a mesh without point normals: bends sharper than this stay sharp.
  double featureAngleDegrees = 30.0;
  double staticFriction = 0.0;
  double dynamicFriction = 0.0;
  /// N s/m.
  double viscosity = 0.0;
  std::vector<SceneTexture> textures;
  /// The factor on kp, and the solid stiffness maps (SurfaceMaterial.h), in the scene's frame.
  double stiffness = 1.0;
  std::vector<StiffnessRegion> stiffnessRegions;
};

/// The joint that holds a body to the world (Documentation/Dynamics.md).
enum class SceneJoint
{
  Hinge,
  Slide,
  Ball,
  Free
};

/// A body on an object (scene file version 2): the object moves as a rigid body on its joint
/// (paper section 6). Axis and anchor are in the scene's frame, where the object is placed. In a
/// scene that names an MJCF file, the object is bound instead to the file's body `mjcfBody`,
/// and the joint and mass here are unused.
struct SceneBody
{
  std::string mjcfBody;
  SceneJoint joint = SceneJoint::Hinge;
  Vec3 axis{0.0, 0.0, 1.0};
  Vec3 anchor;
  bool limited = false;
  double range[2] = {0.0, 0.0};
  /// Spring toward the start pose (N m/rad or N/m) and viscous damping (N m s/rad or N s/m).
  double stiffness = 0.0;
  double damping = 0.0;
  /// Exactly one of the two is above 0: kg/m^3 of the solid the mesh bounds, or its whole mass.
  double density = 0.0;
  double mass = 0.0;
};

struct SceneObject
{
  /// The mesh file, resolved against the scene file's folder.
  std::string mesh;
  /// File units to metres, applied before the pose.
  double scale = 1.0;
  ScenePose pose;
  SceneMaterial material;
  /// The object is a body when `hasBody`.
  bool hasBody = false;
  SceneBody body;
};

struct SceneDescription
{
  /// The scene file as the caller named it (empty for a description made in code).
  std::string path;
  int version = 1;
  std::vector<SceneObject> objects;
  /// m/s^2 on the bodies, in the scene's frame (a scene has no "up" of its own).
  Vec3 gravity;
  /// An MJCF file (resolved against the scene file's folder) whose bodies the objects bind by
  /// name; empty when the bodies are declared on the objects. Its gravity is the scene's.
  std::string mjcf;
  bool hasBodies() const
  {
    for (const SceneObject& object : objects)
    {
      if (object.hasBody)
      {
        return true;
      }
    }
    return false;
  }
};

} // namespace proxima
