// What a surface feels like beyond its shape (paper sections 3 and 4). A default material is the
// bare algorithm of section 2: each effect costs nothing on a surface that does not use it.
#pragma once

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

struct TextureMap
{
  std::shared_ptr<const TextureImage> image;
  TextureRole role = TextureRole::Bump;
  /// Bump: metres of height per unit of image value. Other roles: ignored (the value scales).
  double amplitude = 0.0;
};

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

  bool hasFriction() const
  {
    return staticFriction > 0.0 || dynamicFriction > 0.0 || viscosity > 0.0;
  }
};

} // namespace proxima
