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
  /// What the image's values modulate: height (bump), friction, viscosity or stiffness.
  TextureRole role = TextureRole::Bump;
  /// Bump maps: metres of height per unit of image value. Other roles: 0.
  double amplitude = 0.0;
  /// The image channel whose values are used.
  TextureChannel channel = TextureChannel::Luminance;
};

/// An object's surface as the scene file gives it: shading, friction, viscosity, texture maps
/// and stiffness.
struct SceneMaterial
{
  /// Whether the object is force shaded.
  SceneShading shading = SceneShading::Off;
  /// For shading On on a mesh without point normals: bends sharper than this stay sharp.
  double featureAngleDegrees = 30.0;
  /// Static friction coefficient mu_s; 0 is a surface without a static phase.
  double staticFriction = 0.0;
  /// Dynamic friction coefficient mu_d; not above mu_s when mu_s is above 0.
  double dynamicFriction = 0.0;
  /// N s/m.
  double viscosity = 0.0;
  /// The texture maps, in the file's order; they need a mesh with texture coordinates.
  std::vector<SceneTexture> textures;
  /// The factor on kp, and the solid stiffness maps (SurfaceMaterial.h), in the scene's frame.
  double stiffness = 1.0;
  /// Solid regions that scale the stiffness about their centres, in the scene's frame.
  std::vector<StiffnessRegion> stiffnessRegions;
};

/// The joint that holds a body to the world (Documentation/Dynamics.md).
enum class SceneJoint
{
  Hinge, ///< A rotation about `axis` through `anchor`.
  Slide, ///< A translation along `axis`.
  Ball,  ///< A rotation in every direction about `anchor`.
  Free   ///< No joint: six degrees of freedom, turning about the centre of mass.
};

/// A body on an object (scene file version 2): the object moves as a rigid body on its joint
/// (paper section 6). Axis and anchor are in the scene's frame, where the object is placed. In a
/// scene that names an MJCF file, the object is bound instead to the file's body `mjcfBody`,
/// and the joint and mass here are unused.
struct SceneBody
{
  /// The name of the MJCF file's body the object binds; empty when the joint is declared here.
  std::string mjcfBody;
  /// The kind of joint.
  SceneJoint joint = SceneJoint::Hinge;
  /// The direction of a hinge's or slide's axis, in the scene's frame.
  Vec3 axis{0.0, 0.0, 1.0};
  /// A point on a hinge's axis, or the ball's centre (m, scene frame).
  Vec3 anchor;
  /// True if the joint coordinate is kept within `range` (hinge and slide only).
  bool limited = false;
  /// Lower and upper limits of the joint coordinate from the start when `limited` (rad for a
  /// hinge, m for a slide); low below high.
  double range[2] = {0.0, 0.0};
  /// Spring toward the start pose (N m/rad or N/m) and viscous damping (N m s/rad or N s/m).
  double stiffness = 0.0;
  /// Viscous damping of the joint (N m s/rad or N s/m).
  double damping = 0.0;
  /// Exactly one of the two is above 0: kg/m^3 of the solid the mesh bounds, or its whole mass.
  double density = 0.0;
  /// The body's whole mass (kg), spread evenly through the solid; 0 when `density` is given.
  double mass = 0.0;
};

/// A stiffer (or softer) sphere inside a tissue: the tetrahedra whose centroids it holds take its
/// Young's modulus (a nodule that is felt).
struct SceneInclusion
{
  /// The sphere's centre (m, scene frame).
  Vec3 center;
  /// Its radius (m).
  double radius = 0.0;
  /// The Young's modulus inside it (Pa).
  double youngsModulus = 0.0;
};

/// A deformable object (scene file version 3, Documentation/Tissue.md): the mesh is wrapped and
/// filled with tetrahedra when the scene is built (or they are read from `tets`), and an elastic
/// solid steps under the proxy. Lengths and the fixed box are in the scene's frame.
struct SceneTissue
{
  /// Young's modulus of the tissue (Pa).
  double youngsModulus = 3000.0;
  /// Poisson's ratio, in [0, 0.5).
  double poissonRatio = 0.45;
  /// kg/m^3.
  double density = 1000.0;
  /// Mass-proportional damping (1/s).
  double damping = 1.0;
  /// The tetrahedra's edge size when the mesh is filled (m); unused with `tets`.
  double tetSize = 0.005;
  /// A .vtu file of tetrahedra (resolved against the scene file's folder), in the mesh file's
  /// units (the object's scale and pose apply); empty: the mesh is wrapped and filled.
  std::string tets;
  /// The box whose vertices are held (scene frame): corners low and high.
  Vec3 fixedLow;
  /// The fixed box's upper corner.
  Vec3 fixedHigh;
  /// Stiffer spheres inside, in the file's order.
  std::vector<SceneInclusion> inclusions;
};

/// One object of a scene: its mesh, how the mesh is scaled and placed, its material, and the
/// body it moves as, if any.
struct SceneObject
{
  /// The mesh file, resolved against the scene file's folder.
  std::string mesh;
  /// File units to metres, applied before the pose.
  double scale = 1.0;
  /// Where the object is placed in the scene, after the scale.
  ScenePose pose;
  /// The object's surface.
  SceneMaterial material;
  /// The object is a body when `hasBody`.
  bool hasBody = false;
  /// The object's body; used only when `hasBody`.
  SceneBody body;
  /// The object is deformable tissue when `hasTissue` (never with a body).
  bool hasTissue = false;
  /// The object's tissue; used only when `hasTissue`.
  SceneTissue tissue;
};

/// A whole scene as a scene file gives it, checked but not loaded (buildScene() loads it).
struct SceneDescription
{
  /// The scene file as the caller named it (empty for a description made in code).
  std::string path;
  /// The scene file version: 1, 2 for bodies, gravity and MJCF, or 3 for tissue.
  int version = 1;
  /// The objects, in the file's order; buildScene() needs at least one.
  std::vector<SceneObject> objects;
  /// m/s^2 on the bodies, in the scene's frame (a scene has no "up" of its own).
  Vec3 gravity;
  /// An MJCF file (resolved against the scene file's folder) whose bodies the objects bind by
  /// name; empty when the bodies are declared on the objects. Its gravity is the scene's.
  std::string mjcf;
  /// True if any object is a body.
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
  /// True if any object is tissue.
  bool hasTissue() const
  {
    for (const SceneObject& object : objects)
    {
      if (object.hasTissue)
      {
        return true;
      }
    }
    return false;
  }
};

} // namespace proxima
