#include "obscura/camera/aperture.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"
#include "obscura/math/sampling.h"

namespace obscura {

namespace {

Point2d polygon_vertex(const Aperture& a, int k) {
  double angle =
      a.rotation_degrees * (std::numbers::pi / 180) + 2 * std::numbers::pi * k / a.blades;
  return {std::cos(angle), std::sin(angle)};
}

}  // namespace

Point2d sample_aperture(const Aperture& a, Point2d u) {
  if (a.blades == 0) return sample_uniform_disk_concentric(u);
  double ox = 2 * u.x - 1, oy = 2 * u.y - 1;
  if (ox == 0 && oy == 0) return {0, 0};
  // The square ring at max-norm r holds area ∝ r², as the polygon ring r·boundary does; along a
  // ring, distance along the square's boundary maps linearly onto the polygon's edges, and a
  // straight edge seen from the centre sweeps area linearly too, so the map preserves area.
  double r = std::max(std::abs(ox), std::abs(oy));
  double a_ = ox / r, b_ = oy / r;
  double t;  // position along the square's boundary, counter-clockwise, in [0, 8)
  if (a_ >= 1 && b_ < 1)
    t = b_ + 1;
  else if (b_ >= 1)
    t = 2 + (1 - a_);
  else if (a_ <= -1)
    t = 4 + (1 - b_);
  else
    t = 6 + (a_ + 1);
  double edge_position = t / 8 * a.blades;
  int k = std::min(int(edge_position), a.blades - 1);
  double s = edge_position - k;
  Point2d v0 = polygon_vertex(a, k), v1 = polygon_vertex(a, k + 1);
  return {r * (v0.x + (v1.x - v0.x) * s), r * (v0.y + (v1.y - v0.y) * s)};
}

bool aperture_contains(const Aperture& a, Point2d p) {
  constexpr double kEpsilon = 1e-12;
  if (a.blades == 0) return p.x * p.x + p.y * p.y <= 1 + kEpsilon;
  for (int k = 0; k < a.blades; ++k) {
    Point2d v0 = polygon_vertex(a, k), v1 = polygon_vertex(a, k + 1);
    double side = (v1.x - v0.x) * (p.y - v0.y) - (v1.y - v0.y) * (p.x - v0.x);
    if (side < -kEpsilon) return false;  // outside this (counter-clockwise) edge
  }
  return true;
}

double aperture_gauge(const Aperture& a, Point2d p) {
  return ApertureGauge(a)(p);
}

// The polygon is the intersection of the half-planes n_k · p ≤ cos(π/B), n_k the unit normal
// through the middle of edge k: the gauge is the largest n_k · p / cos(π/B).
ApertureGauge::ApertureGauge(const Aperture& a) {
  if (a.blades == 0) return;
  const double apothem = std::cos(std::numbers::pi / a.blades);
  for (int k = 0; k < a.blades; ++k) {
    double angle =
        a.rotation_degrees * (std::numbers::pi / 180) + 2 * std::numbers::pi * (k + 0.5) / a.blades;
    normals_.push_back({std::cos(angle) / apothem, std::sin(angle) / apothem});
  }
}

double ApertureGauge::operator()(Point2d p) const {
  if (normals_.empty()) return std::sqrt(p.x * p.x + p.y * p.y);
  double largest = 0;
  for (const Point2d& n : normals_) largest = std::max(largest, p.x * n.x + p.y * n.y);
  return largest;
}

std::pair<double, double> aperture_chord(const Aperture& a, double x) {
  if (a.blades == 0) {
    double h = std::sqrt(std::max(0.0, 1 - x * x));
    return std::abs(x) <= 1 ? std::pair{-h, h} : std::pair{1.0, -1.0};
  }
  // Inside = left of every counter-clockwise edge v0 → v1: e_x·(y − v0.y) ≥ e_y·(x − v0.x),
  // a lower bound on y where the edge runs rightwards, an upper one where it runs leftwards.
  double low = -2, high = 2;
  for (int k = 0; k < a.blades; ++k) {
    Point2d v0 = polygon_vertex(a, k), v1 = polygon_vertex(a, k + 1);
    double ex = v1.x - v0.x, ey = v1.y - v0.y;
    double bound_offset = ey * (x - v0.x);
    if (ex > 0)
      low = std::max(low, v0.y + bound_offset / ex);
    else if (ex < 0)
      high = std::min(high, v0.y + bound_offset / ex);
    else if (-ey * (x - v0.x) < 0)
      return {1.0, -1.0};  // a vertical edge with x on its outside
  }
  return {low, high};
}

double aperture_area(const Aperture& a) {
  if (a.blades == 0) return std::numbers::pi;
  return 0.5 * a.blades * std::sin(2 * std::numbers::pi / a.blades);
}

void validate(const Aperture& a) {
  if (a.blades != 0 && a.blades < 3)
    throw Error("camera.aperture_blades",
                "must be 0 (a circle) or at least 3; got " + number_text(a.blades));
  if (!std::isfinite(a.rotation_degrees))
    throw Error("camera.aperture_rotation_degrees", "must be finite");
}

}  // namespace obscura
