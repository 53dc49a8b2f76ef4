#include "obscura/math/shading_normal.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/math/rng.h"

namespace obscura {
namespace {

Vector3f unit(Vector3f v) {
  return v / std::sqrt(dot(v, v));
}

TEST(VisibleShadingNormal, KeepsANormalThatFacesTheViewer) {
  Vector3f ng{0, 0, 1}, ns = unit({0.2f, 0, 1}), wo = unit({-0.3f, 0.1f, 1});
  Vector3f n = visible_shading_normal(ns, ng, wo);
  EXPECT_NEAR(n.x, ns.x, 1e-6f);
  EXPECT_NEAR(n.y, ns.y, 1e-6f);
  EXPECT_NEAR(n.z, ns.z, 1e-6f);
  // Seen from the back face, the same normal flipped.
  Vector3f back = visible_shading_normal(ns, ng, -wo);
  EXPECT_NEAR(back.x, -ns.x, 1e-6f);
  EXPECT_NEAR(back.z, -ns.z, 1e-6f);
}

TEST(VisibleShadingNormal, SilhouetteCaseByHand) {
  // Geometric normal +Z; the viewer 10° above the surface toward +X; the interpolated normal
  // tilted 30° away from the viewer (toward −X), so dot(ns, wo) = cos(110°) < 0. Flipping it
  // to the viewer (the old rule) would give a normal with z < 0: inside the object.
  const float d = 3.14159265f / 180;
  Vector3f ng{0, 0, 1};
  Vector3f wo{std::cos(10 * d), 0, std::sin(10 * d)};
  Vector3f ns{-std::sin(30 * d), 0, std::cos(30 * d)};
  Vector3f n = visible_shading_normal(ns, ng, wo);
  // In the plane of ns and wo (the XZ plane), unit, wo at cos⁻¹(0.01) from it: n is the unit
  // vector of that plane at angle acos(0.01) from wo, on the +Z side: wo rotated by −89.427°.
  float angle = 10 * d + std::acos(0.01f);  // direction of n measured from +X toward +Z
  EXPECT_NEAR(n.x, std::cos(angle), 1e-5f);
  EXPECT_NEAR(n.y, 0, 1e-6f);
  EXPECT_NEAR(n.z, std::sin(angle), 1e-5f);
  EXPECT_GT(n.z, 0);
}

TEST(VisibleShadingNormal, PropertiesOverRandomConfigurations) {
  Pcg32 rng(7);
  auto random_unit = [&] {
    for (;;) {
      Vector3f v{2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1};
      float l2 = dot(v, v);
      if (l2 > 1e-4f && l2 <= 1) return v / std::sqrt(l2);
    }
  };
  for (int i = 0; i < 100000; ++i) {
    Vector3f ng = random_unit(), ns = random_unit(), wo = random_unit();
    if (std::abs(dot(ng, wo)) < 1e-3f) continue;
    Vector3f n = visible_shading_normal(ns, ng, wo);
    ASSERT_NEAR(dot(n, n), 1, 1e-5f);
    ASSERT_GT(dot(n, ng) * dot(wo, ng), 0) << "not on the viewer's side of the geometry";
    ASSERT_GE(dot(n, wo), kMinViewCosine - 1e-4f) << "the viewer is below its horizon";
    Vector3f side_ns = dot(ns, ng) * dot(wo, ng) < 0 ? -ns : ns;
    // In the plane of (the viewer-side) ns and wo: their triple product with n vanishes.
    ASSERT_NEAR(dot(cross(side_ns, wo), n), 0, 1e-4f);
    if (dot(side_ns, wo) >= kMinViewCosine) {
      ASSERT_NEAR(dot(n, side_ns), 1, 1e-5f);
    }
  }
}

}  // namespace
}  // namespace obscura
