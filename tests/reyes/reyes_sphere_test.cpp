// Analytic spheres (Mesh::analytic_sphere, the scene file's `analytic_sphere`) diced natively
// by REYES, and displaced, against references that do not come from REYES: the tracer's primary
// hits on a fine tessellation of the same sphere (of the sphere of radius r + d for a
// displacement d), the outline of a sphere seen from close by (its seam, its pole), and the
// area of its orthographic disk, πr².
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <string>

#include "obscura/scene/shapes.h"
#include "reyes/reyes_test_scenes.h"

namespace obscura {
namespace {

using testing::centre_ids;
using testing::coverage;
using testing::render_reyes;

// The analytic sphere's mesh; the tracer draws its tessellation into `segments`.
Mesh analytic_sphere(float radius, int segments, uint32_t material) {
  Mesh mesh = make_analytic_sphere(radius, segments);
  mesh.material = material;
  return mesh;
}

TEST(ReyesAnalyticSphere, SeesWhatTheTracerSeesAtTheSameSamples) {
  Scene scene;
  scene.materials = {diffuse_material("grey", Rgb(0.7f)),
                     diffuse_material("red", {0.8f, 0.1f, 0.1f})};
  // 512 segments: the tessellation lies within 2·10⁻⁵ radii (0.001 px here) of the sphere.
  scene.meshes.push_back(analytic_sphere(1, 512, 0));
  scene.meshes.push_back(testing::make_quad("wall", 1, {-3, -3, -1.5f}, {3, -3, -1.5f},
                                            {3, 3, -1.5f}, {-3, 3, -1.5f}));
  scene.instances = {testing::make_instance("sphere", 0), testing::make_instance("wall", 1)};
  scene.instances[0].world_from_object =
      Transform::translate({0.2, -0.1, 0}) * Transform::rotate_x(0.6);  // the pole in view
  scene.lights.push_back(
      testing::make_light("key", PointLight{.position = {3, 4, 5}, .intensity = Rgb(40.f)}));
  scene.camera = testing::make_camera({0.3, 0.4, 4}, {0, 0, 0}, 160, 45);
  const int differ =
      testing::expect_same_coverage(centre_ids(scene, scene.camera, "reyes"),
                                    centre_ids(scene, scene.camera, "direct"), "analytic sphere");
  RecordProperty("pixels_differing", differ);
  // REYES diced the sphere, not its 262,144 triangles.
  const testing::ReyesFrame frame = render_reyes(scene, scene.camera, {.pixel_samples = 1});
  EXPECT_LT(frame.stats.pieces, 1000u);
  RecordProperty("patches", int(frame.stats.pieces));
}

// Seen from 0.7 radii through a 110° lens — once facing the seam (u = 0 faces +Z), once looking
// down at the +Y pole — every sample inside the outline (pixels whose 3 × 3 neighbourhood the
// tracer sees all on the sphere) hits it, at shading rates ¼, 1 and 4.
TEST(ReyesAnalyticSphere, LeavesNoCracksAtItsSeamAndPolesInSteepPerspective) {
  Scene scene;
  scene.materials = {testing::unlit_material(Rgb(1.f))};
  scene.meshes.push_back(analytic_sphere(1, 256, 0));
  scene.instances = {testing::make_instance("sphere", 0)};
  for (const Point3d eye : {Point3d(0.2, 0.3, 1.7), Point3d(0.25, 1.7, 0.2)}) {
    Camera camera = testing::make_camera(eye, {0, 0, 0}, 128, 110);
    camera.film.filter = BoxFilter{0.5};
    const Image traced = centre_ids(scene, camera, "direct");
    for (double rate : {0.25, 1.0, 4.0}) {
      const testing::ReyesFrame frame = render_reyes(
          scene, camera, {.shading_rate = rate, .bucket_size = 8, .pixel_samples = 16});
      const auto [inside, cracked] = testing::count_cracks(traced, frame, camera);
      EXPECT_GT(inside, 2000);
      EXPECT_EQ(cracked, 0) << "eye " << eye.x << " " << eye.y << " " << eye.z << ", shading rate "
                            << rate;
      RecordProperty("inside_pixels_eye_y" + std::to_string(int(eye.y * 10)) + "_rate" +
                         std::to_string(int(rate * 100)),
                     inside);
      EXPECT_TRUE(frame.stats.warnings.empty());
    }
  }
}

// The covered area of an orthographic view of a unit sphere is its disk, πr², within 0.2 % —
// with the poles on the outline (seen from the side) and facing the camera.
TEST(ReyesAnalyticSphere, CoversItsOrthographicDiskByItsArea) {
  constexpr int kSize = 256;
  constexpr double kView = 2.2;
  const Camera camera = testing::orthographic_camera(kView, kSize, kSize);
  for (double tilt : {0.0, std::numbers::pi / 2}) {
    Scene scene;
    scene.materials = {testing::unlit_material(Rgb(1.f))};
    scene.meshes.push_back(analytic_sphere(1, 16, 0));  // the coarse tessellation is not drawn
    scene.instances = {testing::make_instance("sphere", 0)};
    scene.instances[0].world_from_object = Transform::rotate_x(tilt);
    const testing::ReyesFrame frame = render_reyes(scene, camera, {.pixel_samples = 16});
    double covered = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) covered += coverage(frame, camera, x, y);
    const double pixel = kView / kSize;
    EXPECT_NEAR(covered * pixel * pixel / std::numbers::pi, 1.0, 0.002) << "tilt " << tilt;
    RecordProperty("area_over_pi_r2_tilt" + std::to_string(int(tilt * 100)),
                   std::to_string(covered * pixel * pixel / std::numbers::pi));
  }
}

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

// A moving, defocused analytic sphere: the same bits on 1 or 2 threads, in buckets of 8 or 32,
// and in a crop window's region (the sphere's patches do not depend on the region rendered).
TEST(ReyesAnalyticSphere, IsBitIdenticalAcrossThreadsBucketsAndCrops) {
  Scene scene;
  scene.materials = {diffuse_material("grey", Rgb(0.7f))};
  scene.meshes.push_back(analytic_sphere(1, 16, 0));
  scene.instances = {testing::make_instance("sphere", 0)};
  scene.instances[0].motion = {{0, Transform()}, {1.0 / 60, Transform::translate({0.2, 0, 0})}};
  scene.lights.push_back(
      testing::make_light("key", PointLight{.position = {3, 4, 5}, .intensity = Rgb(40.f)}));
  scene.camera = testing::make_camera({0.3, 0.4, 3}, {0, 0, 0}, 64, 50);
  scene.camera.lens.depth_of_field = true;
  scene.camera.lens.f_number = 2.8;
  scene.camera.lens.focus_distance_m = 3;
  FrameSettings settings{.renderer = renderer_named("reyes"), .samples_per_pixel = 1};
  settings.reyes.pixel_samples = 4;
  std::optional<Image> reference;
  for (int threads : {1, 2})
    for (int bucket : {8, 32}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
      settings.reyes.bucket_size = bucket;
      const RenderedFrame frame = render_frame(scene, scene.camera, settings, false);
      if (!reference) reference = frame.film_sums;
      EXPECT_TRUE(same_bits(frame.film_sums, *reference)) << threads << " threads, " << bucket;
    }
  Camera cropped = scene.camera;
  cropped.film.crop = {.x_min = 0.25, .y_min = 0.5, .x_max = 0.75, .y_max = 1};
  const RenderedFrame crop = render_frame(scene, cropped, settings, false);
  const Bounds2i region = cropped.film.crop_pixels();
  bool same = crop.film_sums.width == region.width() && crop.film_sums.height == region.height();
  for (int y = 0; same && y < region.height(); ++y)
    for (int x = 0; x < region.width(); ++x)
      for (int c = 0; c < reference->channels; ++c)
        same = same &&
               crop.film_sums.at(x, y, c) == reference->at(x + region.min.x, y + region.min.y, c);
  EXPECT_TRUE(same);
}

// A unit sphere displaced by 0.2 before a wall, and the sphere of radius 1.2 the tracer draws.
Scene displaced_scene(float radius, float displacement, std::optional<float> bound) {
  Scene scene;
  scene.materials = {diffuse_material("grey", Rgb(0.7f)),
                     diffuse_material("red", {0.8f, 0.1f, 0.1f})};
  scene.materials[0].displacement = displacement;
  scene.materials[0].displacement_bound = bound;
  scene.meshes.push_back(analytic_sphere(radius, 512, 0));
  scene.meshes.push_back(testing::make_quad("wall", 1, {-3, -3, -1.5f}, {3, -3, -1.5f},
                                            {3, 3, -1.5f}, {-3, 3, -1.5f}));
  scene.instances = {testing::make_instance("sphere", 0), testing::make_instance("wall", 1)};
  scene.lights.push_back(
      testing::make_light("key", PointLight{.position = {3, 4, 5}, .intensity = Rgb(40.f)}));
  scene.camera = testing::make_camera({0.3, 0.4, 4}, {0, 0, 0}, 160, 45);
  return scene;
}

TEST(ReyesDisplacement, ADisplacedSphereIsTheLargerSphereTheTracerSees) {
  const Scene larger = displaced_scene(1.2f, 0, std::nullopt);
  const Image traced = centre_ids(larger, larger.camera, "direct");
  const Scene bounded = displaced_scene(1, 0.2f, 0.2f);
  const int differ = testing::expect_same_coverage(centre_ids(bounded, bounded.camera, "reyes"),
                                                   traced, "displaced sphere");
  RecordProperty("pixels_differing", differ);
  EXPECT_TRUE(render_reyes(bounded, bounded.camera, {.pixel_samples = 1}).stats.warnings.empty());
  // An under-stated bound warns once, and leaves no hole: the bounds grow to the real reach.
  const Scene understated = displaced_scene(1, 0.2f, 0.05f);
  testing::expect_same_coverage(centre_ids(understated, understated.camera, "reyes"), traced,
                                "under-stated bound");
  const testing::ReyesFrame frame =
      render_reyes(understated, understated.camera, {.pixel_samples = 1});
  ASSERT_EQ(frame.stats.warnings.size(), 1u);
  EXPECT_NE(frame.stats.warnings[0].find("displacement_bound"), std::string::npos);
  EXPECT_NE(frame.stats.warnings[0].find("'grey'"), std::string::npos);
  EXPECT_GT(frame.stats.displacement_overruns, 0u);
}

// A sphere displaced outwards by a varying texture (0 to 0.1) encloses the unit sphere: every
// sample inside the unit sphere's outline (as the tracer sees it, 3 × 3 neighbourhoods) hits the
// displaced one, at its seam, its pole and everywhere between, at shading rates ¼, 1 and 4.
TEST(ReyesDisplacement, LeavesNoCracksInATextureDisplacedSphere) {
  Scene scene;
  scene.materials = {testing::unlit_material(Rgb(1.f))};
  scene.meshes.push_back(analytic_sphere(1, 256, 0));
  scene.instances = {testing::make_instance("sphere", 0)};
  const Image traced = [&] {
    Camera camera = testing::make_camera({0.25, 1.1, 1.4}, {0, 0, 0}, 128, 100);
    return centre_ids(scene, camera, "direct");
  }();
  Texture bumps;
  bumps.width = bumps.height = 8;
  bumps.channels = 1;
  bumps.encoding = TextureEncoding::kLinear;
  for (int k = 0; k < 64; ++k) bumps.texels_float.push_back(float((k * 37) % 64) / 63);
  scene.textures.push_back(bumps);
  scene.materials[0].displacement = 0.1f;
  scene.materials[0].displacement_texture = TextureRef{.texture = 0};
  Camera camera = testing::make_camera({0.25, 1.1, 1.4}, {0, 0, 0}, 128, 100);
  camera.film.filter = BoxFilter{0.5};
  for (double rate : {0.25, 1.0, 4.0}) {
    const testing::ReyesFrame frame =
        render_reyes(scene, camera, {.shading_rate = rate, .bucket_size = 8, .pixel_samples = 16});
    const auto [inside, cracked] = testing::count_cracks(traced, frame, camera);
    EXPECT_GT(inside, 2000);
    EXPECT_EQ(cracked, 0) << "shading rate " << rate;
    EXPECT_TRUE(frame.stats.warnings.empty());
  }
}

}  // namespace
}  // namespace obscura
