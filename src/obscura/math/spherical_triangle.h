// The spherical triangle a planar triangle projects to on the unit sphere around a point: its
// solid angle, and directions drawn uniformly in it (Arvo 1995, "Stratified sampling of
// spherical triangles"). Area lights use it to sample what a shaded point sees of a triangle.
#pragma once

#include "obscura/math/vector.h"

namespace obscura {

// The solid angle (sr) of triangle (p0, p1, p2) seen from `p`, by Van Oosterom and Strackee's
// formula tan(Ω/2) = |a·(b × c)| / (1 + a·b + b·c + c·a) for the unit directions a, b, c to the
// vertices. In [0, 2π); 0 for a triangle degenerate or containing `p` in its plane.
double triangle_solid_angle(Point3d p, Point3d p0, Point3d p1, Point3d p2);

// A unit direction from `p`, uniform in the solid angle the triangle subtends, for a uniform
// u ∈ [0, 1)². The map keeps strata: nearby u give nearby directions. Precondition: the
// triangle's solid angle is not tiny (≳ 10⁻⁶ sr); below that the result loses precision.
Vector3d sample_spherical_triangle(Point3d p, Point3d p0, Point3d p1, Point3d p2, Point2d u);

}  // namespace obscura
