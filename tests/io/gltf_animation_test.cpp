// glTF node transforms and keyframe interpolation against glm (an independent implementation).
#include "obscura/io/gltf_animation.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace obscura {
namespace {

glm::dquat to_glm(Quaternion q) {
  return glm::dquat(q.w, q.x, q.y, q.z);
}

Quaternion unit(double x, double y, double z, double w) {
  double n = std::sqrt(x * x + y * y + z * z + w * w);
  return {x / n, y / n, z / n, w / n};
}

TEST(GltfAnimation, TrsMatrixMatchesGlm) {
  Vector3d t(1, -2, 3), s(0.5, 2, 3);
  Quaternion q = unit(0.3, -0.5, 0.2, 0.8);
  Matrix4 ours = trs_matrix(t, q, s);
  glm::dmat4 ref = glm::translate(glm::dmat4(1), glm::dvec3(1, -2, 3)) * glm::mat4_cast(to_glm(q)) *
                   glm::scale(glm::dmat4(1), glm::dvec3(0.5, 2, 3));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(ours.m[r][c], ref[c][r], 1e-12) << r << "," << c;
}

TEST(GltfAnimation, SlerpMatchesGlm) {
  Quaternion a = unit(0, 0, 0, 1), b = unit(0, 0.7071, 0, 0.7071), c = unit(0.1, 0.9, -0.3, 0.2);
  for (auto [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{a, c}})
    for (double t : {0.0, 0.25, 0.5, 0.9, 1.0}) {
      Quaternion ours = slerp(p, q, t);
      glm::dquat ref = glm::slerp(to_glm(p), to_glm(q), t);
      // q and −q are the same rotation: compare up to sign.
      double sign =
          (ours.w * ref.w + ours.x * ref.x + ours.y * ref.y + ours.z * ref.z) < 0 ? -1 : 1;
      EXPECT_NEAR(ours.x, sign * ref.x, 1e-9);
      EXPECT_NEAR(ours.y, sign * ref.y, 1e-9);
      EXPECT_NEAR(ours.z, sign * ref.z, 1e-9);
      EXPECT_NEAR(ours.w, sign * ref.w, 1e-9);
    }
}

TEST(GltfAnimation, WithoutScaleKeepsRotationAndTranslation) {
  Quaternion q = unit(0.2, 0.4, -0.1, 0.9);
  Transform r = without_scale(trs_matrix({4, 5, 6}, q, {3, 3, 3}));
  Matrix4 expected = trs_matrix({4, 5, 6}, q, {1, 1, 1});
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(r.matrix().m[i][j], expected.m[i][j], 1e-12);
}

TEST(GltfAnimation, SingularMatricesAreRecognised) {
  EXPECT_FALSE(invertible(trs_matrix({0, 0, 0}, {}, {0, 1, 1})).has_value());
  EXPECT_TRUE(invertible(trs_matrix({0, 0, 0}, {}, {1, 1, 1})).has_value());
}

}  // namespace
}  // namespace obscura
