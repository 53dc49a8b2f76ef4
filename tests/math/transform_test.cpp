#include "obscura/math/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#define GLM_FORCE_DEPTH_ZERO_TO_ONE_OFF
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "obscura/math/error.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

// glm stores matrices column-major: theirs[column][row].
void expect_matrix_near(const Matrix4& ours, const glm::dmat4& theirs, double tolerance) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(ours[r][c], theirs[c][r], tolerance) << "row " << r << " column " << c;
}

void expect_point_near(Point3d a, Point3d b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Transform, TranslateMovesPointsButNotVectorsOrNormals) {
  Transform t = Transform::translate({4, 5, 6});
  EXPECT_EQ(t(Point3d(1, 2, 3)), Point3d(5, 7, 9));
  EXPECT_EQ(t(Vector3d(1, 2, 3)), Vector3d(1, 2, 3));
  EXPECT_EQ(t(Normal3d(0, 1, 0)), Normal3d(0, 1, 0));
}

TEST(Transform, QuarterTurnsAboutTheAxesByHand) {
  // Right-handed: a quarter turn about +Z takes +X to +Y, about +X takes +Y to +Z, about +Y
  // takes +Z to +X.
  expect_point_near(Transform::rotate_z(kPi / 2)(Point3d(1, 0, 0)), {0, 1, 0}, 1e-15);
  expect_point_near(Transform::rotate_x(kPi / 2)(Point3d(0, 1, 0)), {0, 0, 1}, 1e-15);
  expect_point_near(Transform::rotate_y(kPi / 2)(Point3d(0, 0, 1)), {1, 0, 0}, 1e-15);
  // A third of a turn about (1,1,1) cycles the axes: X → Y → Z → X.
  expect_point_near(Transform::rotate(2 * kPi / 3, {1, 1, 1})(Point3d(1, 0, 0)), {0, 1, 0}, 1e-15);
}

TEST(Transform, ScaleByHand) {
  Transform s = Transform::scale(2, 3, 4);
  EXPECT_EQ(s(Point3d(1, 1, 1)), Point3d(2, 3, 4));
  EXPECT_EQ(inverse(s)(Point3d(2, 3, 4)), Point3d(1, 1, 1));
  EXPECT_THROW(Transform::scale(0, 1, 1), Error);
}

TEST(Transform, MatchesGlmForTranslateRotateScale) {
  Pcg32 rng(7);
  for (int i = 0; i < 100; ++i) {
    Vector3d axis(rng.next_float() - 0.5, rng.next_float() - 0.5, rng.next_float() + 0.1);
    double angle = 6 * rng.next_float() - 3;
    Vector3d d(rng.next_float() * 10 - 5, rng.next_float() * 10 - 5, rng.next_float() * 10 - 5);
    Vector3d s(rng.next_float() + 0.5, rng.next_float() + 0.5, -(rng.next_float() + 0.5));

    Transform ours = Transform::translate(d) * Transform::rotate(angle, axis) *
                     Transform::scale(s.x, s.y, s.z);
    glm::dmat4 theirs = glm::translate(glm::dmat4(1), glm::dvec3(d.x, d.y, d.z));
    theirs = glm::rotate(theirs, angle, glm::dvec3(axis.x, axis.y, axis.z));
    theirs = glm::scale(theirs, glm::dvec3(s.x, s.y, s.z));
    expect_matrix_near(ours.matrix(), theirs, 1e-12);
    expect_matrix_near(ours.inverse_matrix(), glm::inverse(theirs), 1e-9);
    EXPECT_NEAR(determinant(ours.matrix()), glm::determinant(theirs), 1e-9);
  }
}

TEST(Transform, LookAtMatchesGlm) {
  Pcg32 rng(11);
  for (int i = 0; i < 100; ++i) {
    Point3d eye(rng.next_float() * 8 - 4, rng.next_float() * 8 - 4, rng.next_float() * 8 - 4);
    Point3d target(rng.next_float() * 8 - 4, rng.next_float() * 8 - 4, rng.next_float() * 8 - 4);
    Vector3d up(rng.next_float() - 0.5, 1, rng.next_float() - 0.5);
    Transform view = Transform::look_at(eye, target, up);
    glm::dmat4 theirs = glm::lookAt(glm::dvec3(eye.x, eye.y, eye.z),
                                    glm::dvec3(target.x, target.y, target.z),
                                    glm::dvec3(up.x, up.y, up.z));
    expect_matrix_near(view.matrix(), theirs, 1e-12);
    expect_matrix_near(view.inverse_matrix(), glm::inverse(theirs), 1e-9);
  }
}

TEST(Transform, LookAtPutsTheTargetOnTheNegativeZAxis) {
  Transform view = Transform::look_at({1, 2, 3}, {1, 2, -7}, {0, 1, 0});
  expect_point_near(view(Point3d(1, 2, 3)), {0, 0, 0}, 1e-15);
  expect_point_near(view(Point3d(1, 2, -7)), {0, 0, -10}, 1e-15);
  expect_point_near(view(Point3d(2, 2, 3)), {1, 0, 0}, 1e-15);  // world +X is camera right
  EXPECT_THROW(Transform::look_at({0, 0, 0}, {0, 0, 0}, {0, 1, 0}), Error);
  EXPECT_THROW(Transform::look_at({0, 0, 0}, {0, 5, 0}, {0, 1, 0}), Error);
}

TEST(Transform, InverseAndCompositionIdentities) {
  Pcg32 rng(3);
  for (int i = 0; i < 50; ++i) {
    Transform a = Transform::rotate(rng.next_float() * 6, {rng.next_float(), 1, rng.next_float()}) *
                  Transform::translate({rng.next_float(), rng.next_float(), rng.next_float()});
    Transform b = Transform::scale(rng.next_float() + 0.2, rng.next_float() + 0.2, 2) *
                  Transform::rotate_x(rng.next_float());
    Point3d p(rng.next_float() * 4 - 2, rng.next_float() * 4 - 2, rng.next_float() * 4 - 2);
    expect_point_near((a * b)(p), a(b(p)), 1e-12);
    expect_point_near((a * inverse(a))(p), p, 1e-12);
    expect_point_near(inverse(a * b)(p), inverse(b)(inverse(a)(p)), 1e-12);
    Matrix4 product = a.matrix() * a.inverse_matrix();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(product[r][c], r == c ? 1 : 0, 1e-12);
  }
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
  // The plane x + y = 0 has normal (1, 1, 0) and contains the direction (1, −1, 0). Scaling x by 2
  // takes that direction to (2, −1, 0); the normal must become ∝ (1/2, 1, 0), not (2, 1, 0).
  Transform s = Transform::scale(2, 1, 1);
  Normal3d n = s(Normal3d(1, 1, 0));
  EXPECT_DOUBLE_EQ(n.x, 0.5);
  EXPECT_DOUBLE_EQ(n.y, 1.0);
  EXPECT_DOUBLE_EQ(n.z, 0.0);
  EXPECT_DOUBLE_EQ(dot(n, s(Vector3d(1, -1, 0))), 0.0);
  // Transforming the vector (1,1,0) instead would break perpendicularity.
  EXPECT_NE(dot(s(Vector3d(1, 1, 0)), s(Vector3d(1, -1, 0))), 0.0);
}

TEST(Transform, SingularMatrixIsRejected) {
  Matrix4 m = Matrix4::identity();
  m[2][2] = 0;
  EXPECT_FALSE(inverse(m).has_value());
  EXPECT_THROW(Transform{m}, Error);
}

TEST(Transform, HandednessOfMirrors) {
  EXPECT_FALSE(Transform::rotate_y(1).swaps_handedness());
  EXPECT_TRUE(Transform::scale(-1, 1, 1).swaps_handedness());
}

}  // namespace
}  // namespace obscura
