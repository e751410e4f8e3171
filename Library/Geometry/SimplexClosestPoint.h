// The sub-algorithm of GJK: the point of a simplex (1 to 4 vertices) nearest the origin, its
// barycentric weights, and the smallest sub-simplex that holds it.
#pragma once

#include "Core/Vec3.h"

namespace proxima
{

struct GjkVertex;

/// Replaces vertices[0..size) by the smallest face holding the point nearest the origin, writes
/// that point's barycentric weights, updates size, and returns the point. Degenerate simplices
/// (coincident, collinear or coplanar vertices) fall back to their faces, never divide by zero.
Vec3 reduceSimplexToClosest(GjkVertex* vertices, double* weights, int& size);

} // namespace proxima
