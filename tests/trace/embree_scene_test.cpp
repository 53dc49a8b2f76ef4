#include "obscura/trace/embree_scene.h"

#include <gtest/gtest.h>

#include <vector>

#include "obscura/math/error.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

std::shared_ptr<EmbreeDevice> device() {
  return testing::embree_device();
}

Ray ray_from(Point3f o, Vector3f d) {
  Ray r;
  r.origin = o;
  r.direction = d;
  return r;
}

TEST(EmbreeScene, HitsATriangleWhereGeometrySays) {
  EmbreeScene scene(device());
  std::vector<Point3f> p = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  std::vector<uint32_t> i = {0, 1, 2};
  EXPECT_EQ(scene.add_triangle_mesh(p, i), 0u);
  scene.commit();

  // Straight down onto (1, 2, 0) from height 3: t = 3, and (1, 2) = b1·(4,0) + b2·(0,4).
  auto hit = scene.intersect(ray_from({1, 2, 3}, {0, 0, -1}));
  ASSERT_TRUE(hit);
  EXPECT_FLOAT_EQ(hit->t, 3.f);
  EXPECT_EQ(hit->geometry_id, 0u);
  EXPECT_EQ(hit->primitive_id, 0u);
  EXPECT_NEAR(hit->barycentric.x, 0.25f, 1e-6f);
  EXPECT_NEAR(hit->barycentric.y, 0.5f, 1e-6f);
  // A direction of length 2 halves t.
  EXPECT_FLOAT_EQ(scene.intersect(ray_from({1, 2, 3}, {0, 0, -2}))->t, 1.5f);

  EXPECT_FALSE(scene.intersect(ray_from({3, 3, 3}, {0, 0, -1})));  // outside the hypotenuse
  EXPECT_FALSE(scene.intersect(ray_from({1, 2, 3}, {0, 0, 1})));   // pointing away
  Ray short_ray = ray_from({1, 2, 3}, {0, 0, -1});
  short_ray.t_max = 2.9f;
  EXPECT_FALSE(scene.intersect(short_ray));
  EXPECT_FALSE(scene.occluded(short_ray));
  short_ray.t_max = 3.1f;
  EXPECT_TRUE(scene.occluded(short_ray));
}

TEST(EmbreeScene, ClosestOfSeveralMeshesWins) {
  EmbreeScene scene(device());
  std::vector<Point3f> near_quad = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  std::vector<Point3f> far_quad = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}};
  std::vector<uint32_t> quad = {0, 1, 2, 0, 2, 3};
  uint32_t far_id = scene.add_triangle_mesh(far_quad, quad);
  uint32_t near_id = scene.add_triangle_mesh(near_quad, quad);
  scene.commit();
  auto hit = scene.intersect(ray_from({0.3f, 0.2f, 5}, {0, 0, -1}));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->geometry_id, near_id);
  EXPECT_FLOAT_EQ(hit->t, 4.f);
  auto from_below = scene.intersect(ray_from({0.3f, 0.2f, -5}, {0, 0, 1}));
  ASSERT_TRUE(from_below);
  EXPECT_EQ(from_below->geometry_id, far_id);
}

TEST(EmbreeScene, GeometricNormalFollowsTheWinding) {
  // Counter-clockwise seen from +Z: (p1 − p0) × (p2 − p0) = +Z, whichever side the ray comes from.
  EmbreeScene scene(device());
  std::vector<Point3f> p = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  std::vector<uint32_t> i = {0, 1, 2};
  scene.add_triangle_mesh(p, i);
  scene.commit();
  for (float side : {1.f, -1.f}) {
    std::optional<RayHit> hit = scene.intersect(ray_from({1, 1, 2 * side}, {0, 0, -side}));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->normal.x, 0.f);
    EXPECT_EQ(hit->normal.y, 0.f);
    EXPECT_GT(hit->normal.z, 0.f);
  }
}

TEST(EmbreeScene, RejectsIndicesPastTheVertices) {
  EmbreeScene scene(device());
  std::vector<Point3f> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<uint32_t> bad = {0, 1, 3};
  EXPECT_THROW(scene.add_triangle_mesh(p, bad), Error);
  std::vector<uint32_t> ragged = {0, 1};
  EXPECT_THROW(scene.add_triangle_mesh(p, ragged), Error);
}

}  // namespace
}  // namespace obscura
