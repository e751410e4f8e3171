// What a surface feels like beyond its shape (paper sections 3 and 4). A default material is the
// bare algorithm of section 2: each effect costs nothing on a surface that does not use it.
#pragma once

#include "Core/Vec3.h"
#include "Proxy/TextureImage.h"

#include <memory>
#include <vector>

namespace proxima
{

/// What a texture map modulates (paper 4.3).
enum class TextureRole
{
  /// Height above the surface, amplitude * value metres: perturbs the (shaded) constraint plane
  /// like Blinn's bump mapping. Several bump maps give several constraint planes.
  Bump,
  /// Scales the static and dynamic friction coefficients by value.
  Friction,
  /// Scales the viscosity by value.
  Viscosity,
  /// Scales the servo's spring stiffness kp at the contact by value (a softer or harder spot):
  /// the one effect applied to the force rather than to where the proxy goes.
  Stiffness
};

/// One texture image on a surface and what it modulates, sampled at the contact's texture
/// coordinate (paper 4.3).
struct TextureMap
{
  /// The image, shared and immutable; a null image has no effect.
  std::shared_ptr<const TextureImage> image;
  /// What the image's value modulates.
  TextureRole role = TextureRole::Bump;
  /// Bump: metres of height per unit of image value. Other roles: ignored (the value scales).
  double amplitude = 0.0;
};

/// A region of another stiffness under the surface: a solid stiffness map, such as a hard nodule
/// in soft tissue that a trainee finds by touch. At a contact within `radius` of `center`
/// (metres, in the object as placed in the scene: the region moves with a moving object) the
/// servo's kp is scaled by 1 + (scale - 1) s(1 - d / radius), where d is the contact's distance
/// from the centre and s the smoothstep x^2 (3 - 2x): `scale` at the
/// centre, 1 at the edge, with no step in the force anywhere as the proxy slides across.
struct StiffnessRegion
{
  Vec3 center;         ///< Centre of the region (m), in the object as placed.
  double radius = 0.0; ///< Radius of the region (m); 0 is no region.
  double scale = 1.0;  ///< The factor on kp at the centre.
};

/// The factor `region` puts on kp at `point`.
inline double stiffnessRegionScale(const StiffnessRegion& region, const Vec3& point)
{
  const double distance = norm(point - region.center);
  if (!(distance < region.radius))
  {
    return 1.0;
  }
  const double x = 1.0 - distance / region.radius;
  return 1.0 + (region.scale - 1.0) * x * x * (3.0 - 2.0 * x);
}

/// What a surface feels like beyond its shape: shading, friction, viscosity, textures and
/// stiffness. The default is the bare proxy of paper section 2.
struct SurfaceMaterial
{
  /// Force shading (paper 3, 3.1): constraint planes from the point normals interpolated with the
  /// contact weights, in a two-pass update. Takes effect only on a mesh with point normals.
  bool shading = false;
  /// Static friction mu_s (paper 4.1): the proxy does not move while the finger is inside the
  /// friction cone of a contact. 0: no static friction test.
  double staticFriction = 0.0;
  /// Dynamic friction mu_d (paper 4.2, eq. 21): while sliding, the tangential force is mu_d times
  /// the normal force.
  double dynamicFriction = 0.0;
  /// Viscosity b in N s/m (paper 4.2, eq. 21): bounds the proxy's speed along the surface.
  double viscosity = 0.0;
  /// Texture maps (paper 4.3); they need the mesh's texture coordinates.
  std::vector<TextureMap> textures;
  /// The surface's own factor on the servo's kp: a tissue softer (below 1) or harder than the
  /// scene's stiffness. Stiffness maps and regions scale it further.
  double stiffness = 1.0;
  /// Solid stiffness maps: regions under the surface where kp changes (StiffnessRegion).
  std::vector<StiffnessRegion> stiffnessRegions;

  /// True when any of static friction, dynamic friction or viscosity is on.
  bool hasFriction() const
  {
    return staticFriction > 0.0 || dynamicFriction > 0.0 || viscosity > 0.0;
  }
};

} // namespace proxima
