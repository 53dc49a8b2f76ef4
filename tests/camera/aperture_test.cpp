// Aperture sampling: uniform over the shape, inside it, and centred at u = (½, ½).
#include "obscura/camera/aperture.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "obscura/math/rng.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Aperture, CentreSampleIsTheLensCentre) {
  for (int blades : {0, 5, 6}) {
    Point2d p = sample_aperture({.blades = blades, .rotation_degrees = 10}, {0.5, 0.5});
    EXPECT_EQ(p.x, 0);
    EXPECT_EQ(p.y, 0);
  }
}

TEST(Aperture, SamplesStayInsideTheShape) {
  Pcg32 rng(3);
  for (Aperture a : {Aperture{}, Aperture{.blades = 3, .rotation_degrees = 0},
                     Aperture{.blades = 6, .rotation_degrees = 15}}) {
    for (int i = 0; i < 20000; ++i) {
      Point2d p = sample_aperture(a, {rng.next_float(), rng.next_float()});
      EXPECT_TRUE(aperture_contains(a, p)) << a.blades << " blades: " << p.x << "," << p.y;
    }
  }
}

// Uniformity: the fraction of samples in a region equals the region's share of the area. The
// regions are wedges from the centre and a centred disk of radius ½, whose areas inside a
// regular polygon follow from geometry: a wedge of one blade holds 1/B; the disk of radius ½
// lies inside the polygon when ½ ≤ cos(π/B), holding (π/4) / area.
TEST(Aperture, SamplesAreUniformOverTheArea) {
  constexpr int kSamples = 200000;
  for (int blades : {0, 5, 8}) {
    Aperture a{.blades = blades, .rotation_degrees = 0};
    Pcg32 rng(uint64_t(11 + blades));
    int in_first_wedge = 0, in_small_disk = 0, in_upper_half = 0;
    int wedges = blades == 0 ? 7 : blades;
    for (int i = 0; i < kSamples; ++i) {
      Point2d p = sample_aperture(a, {rng.next_float(), rng.next_float()});
      double angle = std::atan2(p.y, p.x);
      if (angle < 0) angle += 2 * kPi;
      if (angle < 2 * kPi / wedges) ++in_first_wedge;
      if (p.x * p.x + p.y * p.y < 0.25) ++in_small_disk;
      if (p.y > 0) ++in_upper_half;
    }
    double area = blades == 0 ? kPi : 0.5 * blades * std::sin(2 * kPi / blades);
    EXPECT_NEAR(aperture_area(a), area, 1e-12);
    // Binomial standard deviations are about 0.001 at this count; allow 5 of them.
    EXPECT_NEAR(double(in_first_wedge) / kSamples, 1.0 / wedges, 0.005) << blades;
    EXPECT_NEAR(double(in_small_disk) / kSamples, kPi / 4 / area, 0.005) << blades;
    // Vertices at angles ±2πk/B make every shape symmetric about the x axis.
    EXPECT_NEAR(double(in_upper_half) / kSamples, 0.5, 0.005) << blades;
  }
}

TEST(Aperture, RotationTurnsThePolygon) {
  Aperture a{.blades = 4, .rotation_degrees = 45};  // a square with vertices on the diagonals
  EXPECT_TRUE(aperture_contains(a, {0.7, 0.7}));
  EXPECT_FALSE(aperture_contains(a, {0.9, 0}));
  EXPECT_TRUE(aperture_contains(a, {0.7, 0}));
}

}  // namespace
}  // namespace obscura
