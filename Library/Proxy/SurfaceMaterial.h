// What a surface feels like beyond its shape (paper sections 3 and 4). A default material is the
// bare algorithm of section 2: each effect costs nothing on a surface that does not use it.
#pragma once

namespace proxima
{

struct SurfaceMaterial
{
  /// Force shading (paper 3, 3.1): constraint planes from the point normals interpolated with the
  /// contact weights, in a two-pass update. Takes effect only on a mesh with point normals.
  bool shading = false;
};

} // namespace proxima
