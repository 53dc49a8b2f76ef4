// The tracer's compiled scene: Embree instancing must place, shade and identify instances
// exactly as world-space copies of their meshes would.
#include "obscura/trace/trace_scene.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/math/rng.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

std::shared_ptr<EmbreeDevice> device() {
  return testing::embree_device();
}

Instance placed(uint32_t mesh, const Transform& world_from_object) {
  Instance instance;
  instance.name = "copy";
  instance.mesh = mesh;
  instance.world_from_object = world_from_object;
  return instance;
}

// One sphere mesh (with shading normals) placed four times — turned, squashed, mirrored — a
// floor placed once, and one emissive quad mesh placed twice (once mirrored).
Scene shared_meshes_scene() {
  Scene scene;
  scene.name = "instances";
  scene.materials = {diffuse_material("grey", Rgb(0.6f)),
                     diffuse_material("red", Rgb(0.8f, 0.2f, 0.1f)),
                     diffuse_material("lamp", Rgb(0.f), Rgb(4.f))};
  Mesh sphere = testing::make_sphere({0, 0, 0}, 0.4f, 1, 12, 24);
  for (Point3f p : sphere.positions) sphere.normals.push_back(Normal3f(normalize(to_vector(p))));
  uint32_t s = scene.add_mesh(std::move(sphere), Transform::translate({-1, 0.4, 0}));
  const Transform placements[] = {
      Transform::translate({0, 0.4, -0.5}) * Transform::rotate_y(0.7),
      Transform::translate({1, 0.3, 0}) * Transform::scale(1.2, 0.6, 0.9),
      Transform::translate({0.3, 0.4, 0.8}) * Transform::scale(-1, 1, 1) *
          Transform::rotate_x(0.4)};
  for (const Transform& t : placements) scene.instances.push_back(placed(s, t));
  scene.instances.back().material = 0;  // one instance overrides the mesh's material
  scene.add_mesh(testing::make_quad("floor", 0, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}));
  uint32_t lamp =
      scene.add_mesh(testing::make_quad("lamp", 2, {-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f},
                                        {0.5f, 0, 0.5f}, {-0.5f, 0, 0.5f}),  // facing down
                     Transform::translate({-0.6, 2, 0}));
  scene.instances.push_back(
      placed(lamp, Transform::translate({0.8, 2.2, 0}) * Transform::scale(1, 1, -1)));
  scene.camera = testing::make_camera({0, 1.6, 3.5}, {0, 0.4, 0}, 48, 50);
  return scene;
}

TEST(TraceScene, InstancesAreBuiltOncePerMesh) {
  Scene scene = shared_meshes_scene();
  TraceScene automatic(scene, device());
  EXPECT_EQ(automatic.prototype_count(), 2u);        // the sphere and the lamp quad
  EXPECT_EQ(automatic.embree_instance_count(), 6u);  // their 4 + 2 placements; the floor is copied
  TraceScene always(scene, device(), {.instancing = Instancing::kAlways});
  EXPECT_EQ(always.prototype_count(), 3u);
  EXPECT_EQ(always.embree_instance_count(), 7u);
  TraceScene never(scene, device(), {.instancing = Instancing::kNever});
  EXPECT_EQ(never.embree_instance_count(), 0u);
}

TEST(TraceScene, InstancedHitsMatchWorldSpaceCopies) {
  // Random rays into the scene: the same surface, at the same point, with the same normals,
  // ids and material, whether the instance is traversed by Embree or copied into the world.
  Scene scene = shared_meshes_scene();
  TraceScene flat(scene, device(), {.instancing = Instancing::kNever});
  TraceScene instanced(scene, device(), {.instancing = Instancing::kAlways});
  Pcg32 rng(5);
  int hits = 0;
  for (int i = 0; i < 4000; ++i) {
    Ray ray;
    ray.origin = {4 * rng.next_float() - 2, 3, 4 * rng.next_float() - 2};
    ray.direction = normalize(Vector3f(rng.next_float() - 0.5f, -1, rng.next_float() - 0.5f));
    std::optional<SurfaceHit> a = flat.intersect(ray), b = instanced.intersect(ray);
    ASSERT_EQ(bool(a), bool(b)) << "ray " << i;
    if (!a) continue;
    // Rays within float rounding of an edge may pick the neighbour: compare only clear hits.
    if (a->mesh != b->mesh || a->primitive != b->primitive) {
      EXPECT_NEAR(a->t, b->t, 1e-3f) << "ray " << i;
      continue;
    }
    ++hits;
    EXPECT_NEAR(a->t, b->t, 2e-5f * a->t) << "ray " << i;
    EXPECT_EQ(a->material, b->material);
    // Shading normals: the copies interpolate world-space normals, instances interpolate in
    // object space and transform; under non-uniform scale the two differ slightly.
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(a->geometric_normal[c], b->geometric_normal[c], 1e-4f) << "ray " << i;
      EXPECT_NEAR(a->shading_normal[c], b->shading_normal[c], 3e-2f) << "ray " << i;
    }
  }
  EXPECT_GT(hits, 3000);
}

TEST(TraceScene, StaticSceneRendersTheSameWithAndWithoutInstancing) {
  // The same image within float rounding: path by path the same random numbers, so pixels may
  // differ only where a rounding difference changes a discrete decision (an edge hit), and on
  // the non-uniformly scaled instance, whose shading normals are interpolated in object space.
  Scene scene = shared_meshes_scene();
  const int size = scene.camera.film.width_px;
  std::vector<Film> films;
  for (Instancing mode : {Instancing::kNever, Instancing::kAlways}) {
    TraceScene trace(scene, device(), {.instancing = mode});
    films.emplace_back(size, size);
    render(trace, scene.camera, PathTracer({.max_depth = 6}), {.samples_per_pixel = 16, .seed = 9},
           films.back());
  }
  int close = 0;
  double sum[2] = {};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      Rgb a = films[0].pixel({x, y}), b = films[1].pixel({x, y});
      ASSERT_TRUE(std::isfinite(luminance(a)) && std::isfinite(luminance(b))) << x << ", " << y;
      sum[0] += luminance(a), sum[1] += luminance(b);
      close += std::abs(luminance(a) - luminance(b)) <= 1e-4f * (1 + luminance(a));
    }
  EXPECT_GT(sum[0], 0.05 * size * size);  // a lit image, not a black one
  // Measured: 97.7 % of pixels agree to 10⁻⁴; the rest are the squashed sphere, whose shading
  // normals interpolate differently (see above), and a few edge pixels.
  EXPECT_GE(close, int(0.96 * size * size));
  EXPECT_NEAR(sum[1] / sum[0], 1.0, 5e-3);
}

}  // namespace
}  // namespace obscura
