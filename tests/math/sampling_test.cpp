#include "obscura/math/sampling.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/math/rng.h"

namespace obscura {
namespace {

constexpr int kN = 200000;

Point2f random_2d(Pcg32& rng) {
  float u = rng.next_float();
  return {u, rng.next_float()};
}

// Monte Carlo means are compared with their analytic values within 5 standard errors.
TEST(Sampling, CosineHemisphereMoments) {
  Pcg32 rng(1);
  double sum_cos = 0, sum_cos2 = 0;
  for (int i = 0; i < kN; ++i) {
    Vector3f w = sample_cosine_hemisphere(random_2d(rng));
    ASSERT_GE(w.z, 0.f);
    ASSERT_NEAR(length(w), 1.f, 1e-5f);
    sum_cos += w.z;
    sum_cos2 += w.z * w.z;
  }
  // For p(ω) = cosθ/π: E[cosθ] = 2/3, E[cos²θ] = 1/2.
  double sigma = std::sqrt(0.5 - 4.0 / 9.0) / std::sqrt(double(kN));
  EXPECT_NEAR(sum_cos / kN, 2.0 / 3.0, 5 * sigma);
  EXPECT_NEAR(sum_cos2 / kN, 0.5, 0.005);
}

TEST(Sampling, UniformHemisphereAndSphereMoments) {
  Pcg32 rng(2);
  double hemi_z = 0, sphere_z = 0, sphere_z2 = 0;
  for (int i = 0; i < kN; ++i) {
    Vector3f h = sample_uniform_hemisphere(random_2d(rng));
    Vector3f s = sample_uniform_sphere(random_2d(rng));
    ASSERT_GE(h.z, 0.f);
    ASSERT_NEAR(length(h), 1.f, 1e-5f);
    ASSERT_NEAR(length(s), 1.f, 1e-5f);
    hemi_z += h.z, sphere_z += s.z, sphere_z2 += s.z * s.z;
  }
  // Uniform on the hemisphere: E[z] = 1/2, Var = 1/12; on the sphere E[z] = 0, E[z²] = 1/3.
  double sigma = std::sqrt(1.0 / 12) / std::sqrt(double(kN));
  EXPECT_NEAR(hemi_z / kN, 0.5, 5 * sigma);
  EXPECT_NEAR(sphere_z / kN, 0.0, 5 * std::sqrt(1.0 / 3 / kN));
  EXPECT_NEAR(sphere_z2 / kN, 1.0 / 3.0, 0.005);
}

TEST(Sampling, ConcentricDiskIsUniformAndMapsEdgesToTheRim) {
  Pcg32 rng(3);
  int quadrant[4] = {};
  double r2 = 0;
  for (int i = 0; i < kN; ++i) {
    Point2f d = sample_uniform_disk_concentric(random_2d(rng));
    float rr = d.x * d.x + d.y * d.y;
    ASSERT_LE(rr, 1.f + 1e-6f);
    r2 += rr;
    ++quadrant[(d.x >= 0 ? 0 : 1) + (d.y >= 0 ? 0 : 2)];
  }
  EXPECT_NEAR(r2 / kN, 0.5, 0.005);  // E[r²] = 1/2 for a uniform unit disk
  for (int q : quadrant) EXPECT_NEAR(q, kN / 4, 5 * std::sqrt(kN * 0.25 * 0.75));
  Point2f rim = sample_uniform_disk_concentric(Point2f{1.f, 0.5f});
  EXPECT_NEAR(rim.x, 1.f, 1e-6f);
  EXPECT_NEAR(rim.y, 0.f, 1e-6f);
  Point2f centre = sample_uniform_disk_concentric(Point2f{0.5f, 0.5f});
  EXPECT_EQ(centre, Point2f(0, 0));
}

TEST(Sampling, PolarDiskIsUniform) {
  Pcg32 rng(4);
  double r2 = 0;
  for (int i = 0; i < kN; ++i) {
    Point2f d = sample_uniform_disk_polar(random_2d(rng));
    r2 += d.x * d.x + d.y * d.y;
  }
  EXPECT_NEAR(r2 / kN, 0.5, 0.005);
}

TEST(Sampling, TriangleBarycentricsAreUniform) {
  Pcg32 rng(5);
  double b0 = 0, b1 = 0;
  for (int i = 0; i < kN; ++i) {
    Point2f b = sample_uniform_triangle(random_2d(rng));
    ASSERT_GE(b.x, 0.f);
    ASSERT_GE(b.y, 0.f);
    ASSERT_LE(b.x + b.y, 1.f + 1e-6f);
    b0 += b.x, b1 += b.y;
  }
  // The centroid: each barycentric coordinate averages 1/3 (variance 1/18).
  double sigma = std::sqrt(1.0 / 18 / kN);
  EXPECT_NEAR(b0 / kN, 1.0 / 3.0, 5 * sigma);
  EXPECT_NEAR(b1 / kN, 1.0 / 3.0, 5 * sigma);
}

}  // namespace
}  // namespace obscura
