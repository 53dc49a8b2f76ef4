// Keyframed camera motion: constant-rate rotation (slerp), linear translation, held ends.
#include "obscura/camera/animated_transform.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_point_near(Point3d a, Point3d b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(AnimatedTransform, RotatesAtAConstantRateAndTranslatesLinearly) {
  // From the origin facing −Z to (2, 0, 0) turned 90° about +Y, over one second.
  AnimatedTransform motion(
      {{0, Transform()}, {1, Transform::translate({2, 0, 0}) * Transform::rotate_y(kPi / 2)}});
  for (double t : {0.0, 0.25, 0.5, 1.0}) {
    Transform at = motion.at(t);
    expect_point_near(at(Point3d(0, 0, 0)), {2 * t, 0, 0});
    // The forward axis −Z turns by 90°·t about +Y: (−sin θ, 0, −cos θ).
    double theta = kPi / 2 * t;
    Vector3d forward = at(Vector3d(0, 0, -1));
    EXPECT_NEAR(forward.x, -std::sin(theta), 1e-12);
    EXPECT_NEAR(forward.y, 0, 1e-12);
    EXPECT_NEAR(forward.z, -std::cos(theta), 1e-12);
    // Still a rigid motion: the inverse really is the inverse.
    expect_point_near(inverse(at)(at(Point3d(0.3, -1, 2))), {0.3, -1, 2});
  }
}

TEST(AnimatedTransform, HoldsTheEndKeysOutsideTheirRange) {
  AnimatedTransform motion(
      {{1, Transform::translate({1, 0, 0})}, {2, Transform::translate({3, 0, 0})}});
  expect_point_near(motion.at(0)(Point3d(0, 0, 0)), {1, 0, 0});
  expect_point_near(motion.at(5)(Point3d(0, 0, 0)), {3, 0, 0});
  expect_point_near(motion.at(1.5)(Point3d(0, 0, 0)), {2, 0, 0});
  EXPECT_TRUE(motion.is_animated());
  EXPECT_FALSE(AnimatedTransform(Transform()).is_animated());
}

TEST(AnimatedTransform, RejectsBadKeys) {
  EXPECT_THROW(AnimatedTransform(std::vector<AnimatedTransform::Key>{}), Error);
  EXPECT_THROW(AnimatedTransform({{1, Transform()}, {1, Transform()}}), Error);
  Matrix4 shear = Matrix4::identity();
  shear[0][1] = 0.5;
  EXPECT_THROW(AnimatedTransform({{0, Transform()}, {1, Transform(shear)}}), Error);
}

}  // namespace
}  // namespace obscura
