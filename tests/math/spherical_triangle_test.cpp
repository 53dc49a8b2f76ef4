#include "obscura/math/spherical_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "../trace/bsdf_test_support.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SphericalTriangle, SolidAngleOfAnOctant) {
  // The triangle x + y + z = 1 in the first octant projects from the origin onto exactly one
  // eighth of the sphere: 4π/8.
  EXPECT_NEAR(triangle_solid_angle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), kPi / 2, 1e-12);
  // Seen from the other side, and with the winding reversed: the same.
  EXPECT_NEAR(triangle_solid_angle({0, 0, 0}, {2, 0, 0}, {0, 0, 2}, {0, 2, 0}), kPi / 2, 1e-12);
}

TEST(SphericalTriangle, SolidAngleMatchesVanOosteromStrackeByHand) {
  // Vertices r1 = (0,0,−1), r2 = (1,0,−1), r3 = (0,1,−1) from the origin: |r1| = 1, |r2| = |r3|
  // = √2, r1·(r2 × r3) = (0,0,−1)·(1,1,1) = −1, r1·r2 = r1·r3 = r2·r3 = 1, so
  // tan(Ω/2) = 1 / (1·√2·√2 + 1·√2 + 1·√2 + 1·1) = 1 / (3 + 2√2) = 3 − 2√2.
  const double by_hand = 2 * std::atan(3 - 2 * std::sqrt(2.0));  // 0.339837…
  EXPECT_NEAR(triangle_solid_angle({0, 0, 0}, {0, 0, -1}, {1, 0, -1}, {0, 1, -1}), by_hand, 1e-12);
  // With the other half of the unit square it covers the square (0..1)² at distance 1 seen from
  // above a corner: atan(ab / (d·√(a² + b² + d²))) = atan(1/√3) = π/6.
  double other = triangle_solid_angle({0, 0, 0}, {1, 0, -1}, {1, 1, -1}, {0, 1, -1});
  EXPECT_NEAR(by_hand + other, kPi / 6, 1e-12);
}

// Where a direction from p meets the plane of triangle (p0, p1, p2), in barycentrics (b1, b2).
Point2d barycentrics(Point3d p, Vector3d w, Point3d p0, Point3d p1, Point3d p2) {
  Vector3d e1 = p1 - p0, e2 = p2 - p0, n = cross(e1, e2);
  double t = dot(n, p0 - p) / dot(n, w);
  Vector3d q = (p + w * t) - p0;
  // Solve q = b1·e1 + b2·e2 by the normal equations.
  double a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2);
  double r1 = dot(q, e1), r2 = dot(q, e2), det = a11 * a22 - a12 * a12;
  return {(a22 * r1 - a12 * r2) / det, (a11 * r2 - a12 * r1) / det};
}

// Chi-square test of SphericalTriangle::sample against the uniform density 1/Ω. The triangle is
// cut into n² congruent sub-triangles (a barycentric grid); each one's expected share is its own
// solid angle over the whole, integrated by the midpoint rule of cos θ/d² over a finer grid —
// independently of the formulas under test.
void expect_uniform_in_solid_angle(Point3d p, Point3d p0, Point3d p1, Point3d p2) {
  constexpr int n = 8, fine = 16, samples = 200000;
  Vector3d normal = normalize(cross(p1 - p0, p2 - p0));
  double area = 0.5 * length(cross(p1 - p0, p2 - p0));
  auto point = [&](double b1, double b2) { return p0 + (p1 - p0) * b1 + (p2 - p0) * b2; };
  // Bin index of barycentrics (b1, b2): the grid cell (i, j) and its lower or upper half.
  auto bin_of = [&](Point2d b) {
    double x = std::clamp(b.x * n, 0.0, n - 1e-9), y = std::clamp(b.y * n, 0.0, n - 1e-9);
    int i = int(x), j = int(y);
    bool upper = (x - i) + (y - j) > 1;
    return (i * n + j) * 2 + int(upper);
  };
  std::vector<double> expected(2 * n * n, 0.0);
  const int m = n * fine;
  double micro_area = area / (m * m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m - i; ++j)
      for (int upper = 0; upper < (i + j < m - 1 ? 2 : 1); ++upper) {
        // Centroid of micro-triangle (i, j, lower/upper) in barycentrics.
        double b1 = (i + (upper ? 2.0 : 1.0) / 3) / m, b2 = (j + (upper ? 2.0 : 1.0) / 3) / m;
        Vector3d d = point(b1, b2) - p;
        double d2 = dot(d, d), cos_theta = std::abs(dot(normal, d)) / std::sqrt(d2);
        expected[bin_of({b1, b2})] += cos_theta / d2 * micro_area;
      }
  double omega = 0;
  for (double e : expected) omega += e;
  EXPECT_NEAR(omega, triangle_solid_angle(p, p0, p1, p2), 2e-3 * omega);

  std::vector<double> observed(expected.size(), 0.0);
  Pcg32 rng(7);
  SphericalTriangle spherical(p, p0, p1, p2);
  for (int s = 0; s < samples; ++s) {
    Vector3d w = spherical.sample({double(rng.next_float()), double(rng.next_float())});
    ASSERT_NEAR(length(w), 1.0, 1e-9);
    Point2d b = barycentrics(p, w, p0, p1, p2);
    ASSERT_GE(b.x, -1e-6);
    ASSERT_GE(b.y, -1e-6);
    ASSERT_LE(b.x + b.y, 1 + 1e-6);
    observed[bin_of(b)] += 1;
  }
  double chi2 = 0;
  int bins = 0;
  for (size_t k = 0; k < expected.size(); ++k) {
    if (expected[k] == 0) {  // a grid cell's missing upper half beyond the hypotenuse
      EXPECT_EQ(observed[k], 0);
      continue;
    }
    double e = expected[k] / omega * samples;
    chi2 += (observed[k] - e) * (observed[k] - e) / e;
    ++bins;
  }
  EXPECT_EQ(bins, n * n);
  int dof = bins - 1;
  EXPECT_GT(testing::chi_square_p_value(chi2, dof), testing::kChiSquareSignificance)
      << "chi2 " << chi2 << " with " << dof << " degrees of freedom";
}

TEST(SphericalTriangle, SamplesAreUniformInSolidAngle) {
  // Far and small (d²/cos nearly constant), close and large (Ω ≈ 2.3 sr, strongly varying),
  // seen obliquely, and with the winding reversed.
  expect_uniform_in_solid_angle({0, 0, 0}, {-0.1, -0.1, -3}, {0.2, -0.1, -3}, {0, 0.15, -3});
  expect_uniform_in_solid_angle({0, 0, 0}, {-1, -1, -0.4}, {1.5, -1, -0.4}, {0, 1, -0.4});
  expect_uniform_in_solid_angle({0.3, 0.1, 0}, {0, 1, -1}, {2, 0.5, -2}, {-1, 0.2, -0.5});
  expect_uniform_in_solid_angle({0, 0, 0}, {0, 1, -0.4}, {1.5, -1, -0.4}, {-1, -1, -0.4});
}

}  // namespace
}  // namespace obscura
