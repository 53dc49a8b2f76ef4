// The spherical triangle a planar triangle projects to on the unit sphere around a point: its
// solid angle, and directions drawn uniformly in it (Arvo 1995, "Stratified sampling of
// spherical triangles"). Area lights use it to sample what a shaded point sees of a triangle.
#pragma once

#include "obscura/math/vector.h"

namespace obscura {

class SphericalTriangle {
 public:
  // Triangle (p0, p1, p2) seen from `p`.
  SphericalTriangle(Point3d p, Point3d p0, Point3d p1, Point3d p2);

  // The solid angle (sr), by Van Oosterom and Strackee's formula tan(Ω/2) = |a·(b × c)| /
  // (1 + a·b + b·c + c·a) for the unit directions a, b, c to the vertices. In [0, 2π); 0 for a
  // degenerate triangle or one whose plane contains p.
  double solid_angle() const { return solid_angle_; }

  // A unit direction uniform in the spherical triangle for a uniform u ∈ [0, 1)²; nearby u give
  // nearby directions (strata are kept). Precondition: solid_angle() is not tiny (≳ 10⁻⁶ sr);
  // below that the result loses precision.
  Vector3d sample(Point2d u) const;

 private:
  Vector3d a_, b_, c_;  // unit directions to the vertices
  double solid_angle_ = 0;
  double triple_ = 0;  // |a·(b × c)|
};

// SphericalTriangle(p, p0, p1, p2).solid_angle().
double triangle_solid_angle(Point3d p, Point3d p0, Point3d p1, Point3d p2);

}  // namespace obscura
