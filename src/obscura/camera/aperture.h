// The shape of the lens opening, which is the shape out-of-focus highlights take (bokeh): a
// circle, or a regular polygon of B straight blades turned by a rotation.
#pragma once

#include <utility>
#include <vector>

#include "obscura/math/vector.h"

namespace obscura {

struct Aperture {
  int blades = 0;               // 0: a circle; otherwise ≥ 3, a regular polygon
  double rotation_degrees = 0;  // turns the polygon counter-clockwise (seen from the film)
};

// A uniformly distributed point of the aperture inscribed in the unit circle, from u ∈ [0,1)².
// Both shapes use a concentric mapping (Shirley–Chiu 1997, extended to polygons by following the
// square's boundary onto the polygon's), so u = (½, ½) is the centre and nearby u stay nearby.
Point2d sample_aperture(const Aperture& a, Point2d u);
// Whether p (unit-circle coordinates) lies inside the aperture, boundary included.
bool aperture_contains(const Aperture& a, Point2d p);
// The smallest s for which p lies in the aperture scaled by s (its gauge): ≤ 1 exactly where
// aperture_contains holds (up to rounding), and continuous, so that it can be interpolated
// between traced rays to find the aperture's edge between them (lens flare's ghosts).
double aperture_gauge(const Aperture& a, Point2d p);
// The same with the blades' directions computed once, for many points.
class ApertureGauge {
 public:
  explicit ApertureGauge(const Aperture& a);
  double operator()(Point2d p) const;

 private:
  std::vector<Point2d> normals_;  // per edge: its outward normal over the polygon's apothem
};
// The aperture's extent along y at abscissa x (unit-circle coordinates): [first, second], empty
// (first > second) where x misses the shape.
std::pair<double, double> aperture_chord(const Aperture& a, double x);
// Area of the aperture inscribed in the unit circle: π for the circle, (B/2)·sin(2π/B) for B
// blades.
double aperture_area(const Aperture& a);

// Throws obscura::Error naming the value when blades is neither 0 nor ≥ 3.
void validate(const Aperture& a);

}  // namespace obscura
