// Keyframed motion (cameras and instances): constant-rate rotation (slerp), linear translation,
// held ends; keys with shear through the polar decomposition, checked against its 2D closed form
// and against the rigid motion an exporter's float-noise scale barely disturbs.
#include "obscura/camera/animated_transform.h"

#include <cmath>
#include <numbers>
#include <string>

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
  Matrix4 projective = Matrix4::identity();
  projective[3][2] = 0.5;  // invertible, but not affine: no translation · rotation · stretch
  try {
    AnimatedTransform({{0, Transform()}, {1, Transform(projective)}});
    ADD_FAILURE() << "a projective key was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("motion key 1"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("camera"), std::string::npos) << e.what();
  }
}

// A shear in the xy-plane, M = [[1, h], [0, 1]]: its polar rotation turns by θ = atan2(c − b,
// a + d) = atan2(−h, 2) (the closed form for 2 × 2 matrices), its stretch is R(θ)ᵀ · M, and half
// way from the identity the motion is R(θ/2) · (I + S)/2.
TEST(AnimatedTransform, KeysWithShearInterpolateThroughThePolarDecomposition) {
  const double h = 0.5;
  Matrix4 shear = Matrix4::identity();
  shear[0][1] = h;
  const AnimatedTransform motion(
      {{0, Transform()}, {1, Transform(shear)}, {2, Transform::translate({0, 0, 1})}});
  // At the middle key the shear comes back exactly (to rounding).
  const Transform at_key = motion.at(1);
  for (int row = 0; row < 4; ++row)
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(at_key.matrix()[row][c], shear[row][c], 1e-12) << row << "," << c;
  const double theta = std::atan2(-h, 2.0);
  const double cos_t = std::cos(theta), sin_t = std::sin(theta);
  // S = R(θ)ᵀ · M, 2 × 2 block.
  const double s00 = cos_t, s01 = cos_t * h + sin_t, s10 = -sin_t, s11 = -sin_t * h + cos_t;
  const double m00 = (1 + s00) / 2, m01 = s01 / 2, m10 = s10 / 2, m11 = (1 + s11) / 2;
  const double c2 = std::cos(theta / 2), s2 = std::sin(theta / 2);
  const Transform half = motion.at(0.5);
  for (Point3d p : {Point3d(1, 0, 0), Point3d(0, 1, 0), Point3d(0.3, -2, 5)}) {
    const double x = m00 * p.x + m01 * p.y, y = m10 * p.x + m11 * p.y;
    expect_point_near(half(p), {c2 * x - s2 * y, s2 * x + c2 * y, p.z}, 1e-12);
    expect_point_near(inverse(half)(half(p)), p, 1e-12);
  }
}

// RobotExpressive.glb's legs: a parent scaled (1, 0.99997, 1.0000156) by an exporter's float
// noise over a child turning 90°: the world keys have shear of about 1e-5, and the motion must
// still be the child's rotation, to the size of the noise.
TEST(AnimatedTransform, FloatNoiseScalesInAHierarchyStillAnimate) {
  const Transform parent = Transform::scale(1, 0.99997, 1.0000156);
  const AnimatedTransform motion({{0, parent * Transform::rotate_x(0)},
                                  {1, parent * Transform::rotate_x(kPi / 4)},
                                  {2, parent * Transform::rotate_x(kPi / 2)}});
  for (double t : {0.25, 0.5, 1.0, 1.5, 1.75}) {
    const Transform rigid = Transform::rotate_x(kPi / 4 * t);
    for (Point3d p : {Point3d(0, 1, 0), Point3d(0, 0, 1), Point3d(0.5, -0.2, 0.7)})
      expect_point_near(motion.at(t)(p), rigid(p), 1e-4);
  }
}

}  // namespace
}  // namespace obscura
