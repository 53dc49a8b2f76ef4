// REYES's visibility against independent references: which surface each pixel sees against the
// tracer's primary hits (Embree, at the same sample positions), the covered area of a disk
// against πr², no background inside a sphere's outline, α-blended planes against the analytic
// `over`, and the image bit for bit across threads, bucket sizes and parts of a frame.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <utility>

#include "gltf_fidelity_scene.h"
#include "obscura/film/image.h"
#include "obscura/io/scene_loader.h"
#include "obscura/render/frame_settings.h"
#include "obscura/render/render_frame.h"
#include "obscura/render/renderer.h"
#include "obscura/scene/builtin_scenes.h"
#include "reyes/reyes_test_scenes.h"

namespace obscura {
namespace {

using testing::centre_ids;
using testing::coverage;
using testing::expect_same_coverage;
using testing::render_reyes;

Scene sphere_scene() {
  Scene scene;
  scene.materials = {diffuse_material("grey", Rgb(0.7f)),
                     diffuse_material("red", {0.8f, 0.1f, 0.1f})};
  scene.meshes.push_back(testing::make_sphere({0, 0, 0}, 1, 0, 24, 48));
  scene.meshes.push_back(testing::make_quad("wall", 1, {-3, -3, -1.5f}, {3, -3, -1.5f},
                                            {3, 3, -1.5f}, {-3, 3, -1.5f}));
  scene.instances = {testing::make_instance("sphere", 0), testing::make_instance("wall", 1)};
  scene.lights.push_back(
      testing::make_light("key", PointLight{.position = {3, 4, 5}, .intensity = Rgb(40.f)}));
  scene.lights.push_back(testing::make_light(
      "sun", DirectionalLight{.direction = {-0.3f, -1, -0.5f}, .irradiance = Rgb(1.f)}));
  scene.camera = testing::make_camera({0.3, 0.4, 4}, {0, 0, 0}, 160, 45);
  return scene;
}

TEST(ReyesVisibility, SeesWhatTheTracerSeesAtTheSameSamples) {
  const Scene sphere = sphere_scene();
  expect_same_coverage(centre_ids(sphere, sphere.camera, "reyes"),
                       centre_ids(sphere, sphere.camera, "direct"), "sphere");
  Scene box = make_cornell_box();
  box.camera.film.width_px = box.camera.film.height_px = 160;
  expect_same_coverage(centre_ids(box, box.camera, "reyes"), centre_ids(box, box.camera, "direct"),
                       "Cornell box");
  // glTF sample models, framed as the glTF fidelity tests frame them (blended surfaces compared
  // as opaque: a blended surface has no one id at a sample).
  for (const auto& [name, model] :
       {std::pair{"Duck", "Duck/Duck.glb"},
        std::pair{"SimpleInstancing", "SimpleInstancing/SimpleInstancing.glb"}}) {
    Scene gltf = test::fidelity_scene(name, model, 160);
    for (Material& material : gltf.materials)
      if (material.alpha_mode == AlphaMode::kBlend) material.alpha_mode = AlphaMode::kOpaque;
    expect_same_coverage(centre_ids(gltf, gltf.camera, "reyes"),
                         centre_ids(gltf, gltf.camera, "direct"), name);
  }
}

// Every built-in scene (`obscura render --scene-list`) renders, finite and lit, and sees what the
// rasterizer sees at the pixel centres (both sample there: a filter too narrow to move the sample).
TEST(ReyesVisibility, RendersEveryBuiltInSceneAsTheRasterizerSeesIt) {
  for (const char* name : {"cornell-box", "cornell-box-obj", "spheres-and-lights", "depth-of-field",
                           "motion-blur", "bunny", "gltf-spheres"}) {
    SCOPED_TRACE(name);
    const Scene scene = load_scene(name);
    Camera camera = scene.camera;
    camera.film.width_px = 64;
    camera.film.height_px = 48;
    // Visibility compared at one moment through the lens centre; the image with every effect.
    Camera sharp = camera;
    sharp.shutter.close_s = sharp.shutter.open_s;
    sharp.lens.depth_of_field = false;
    const Image reyes = centre_ids(scene, sharp, "reyes");
    const Image raster = centre_ids(scene, sharp, "raster");
    int differ = 0;
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) differ += reyes.at(x, y, 0) != raster.at(x, y, 0);
    EXPECT_LE(differ, 64 * 48 / 50);
    FrameSettings settings{.renderer = renderer_named("reyes")};
    settings.reyes.pixel_samples = 2;
    const Image image = render_frame(scene, camera, settings, false).finished();
    double sum = 0;
    for (float v : image.data) {
      EXPECT_TRUE(std::isfinite(v));
      sum += v;
    }
    EXPECT_GT(sum, 0);
  }
}

TEST(ReyesVisibility, CoversAnOrthographicDiskByItsArea) {
  constexpr int kSegments = 4096;
  constexpr float kRadius = 1;
  Scene scene;
  scene.materials = {testing::unlit_material(Rgb(1.f))};
  scene.meshes.push_back(testing::make_disk(kRadius, 0, kSegments, 0));
  scene.instances = {testing::make_instance("disk", 0)};
  constexpr double kView = 2.2;
  constexpr int kSize = 256;
  const Camera camera = testing::orthographic_camera(kView, kSize, kSize);
  const testing::ReyesFrame frame = render_reyes(scene, camera, {.pixel_samples = 16});
  double covered = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) covered += coverage(frame, camera, x, y);
  const double pixel = kView / kSize;
  // The fan's own area: n/2 · r² · sin(2π/n), within 4e-7 of πr².
  const double polygon =
      kSegments / 2.0 * kRadius * kRadius * std::sin(2 * std::numbers::pi / kSegments);
  EXPECT_NEAR(covered * pixel * pixel / polygon, 1.0, 0.002);
  EXPECT_NEAR(covered * pixel * pixel / (std::numbers::pi * kRadius * kRadius), 1.0, 0.002);
}

// A coarse sphere seen from close by through a wide lens: every sample inside its outline (where
// the tracer sees the sphere at a pixel and all its neighbours) must hit it, at any shading rate.
TEST(ReyesVisibility, LeavesNoCracksInASphereInSteepPerspective) {
  Scene scene;
  scene.materials = {testing::unlit_material(Rgb(1.f))};
  scene.meshes.push_back(testing::make_sphere({0, 0, 0}, 1, 0, 16, 32));
  scene.instances = {testing::make_instance("sphere", 0)};
  Camera camera = testing::make_camera({0.2, 0.3, 1.7}, {0, 0, 0}, 128, 110);
  camera.film.filter = BoxFilter{0.5};
  const Image traced = centre_ids(scene, camera, "direct");
  for (double rate : {0.25, 1.0, 4.0}) {
    const testing::ReyesFrame frame =
        render_reyes(scene, camera, {.shading_rate = rate, .bucket_size = 8, .pixel_samples = 16});
    const auto [inside, cracked] = testing::count_cracks(traced, frame, camera);
    EXPECT_GT(inside, 2000);
    EXPECT_EQ(cracked, 0) << "shading rate " << rate;
    EXPECT_GT(frame.stats.micropolygons, 0u);
  }
}

// Three planes of α = ½ (red nearest, then green, then blue) over black: ½ r + ¼ g + ⅛ b, in
// whatever order the scene lists them.
TEST(ReyesVisibility, CompositesTransparentPlanesFrontToBackInAnyOrder) {
  const Rgb colors[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const float depths[3] = {2, 1, 0};  // towards the camera on +Z: red is nearest
  const Camera camera = testing::orthographic_camera(2, 16, 16);
  std::array<int, 3> order = {0, 1, 2};
  std::optional<Image> first;
  do {
    Scene scene;
    for (int k : order) {
      scene.materials.push_back(testing::unlit_material(colors[k], 0.5f, AlphaMode::kBlend));
      const float z = depths[k];
      scene.meshes.push_back(testing::make_quad("plane", uint32_t(scene.materials.size() - 1),
                                                {-5, -5, z}, {5, -5, z}, {5, 5, z}, {-5, 5, z}));
      scene.instances.push_back(testing::make_instance("plane", uint32_t(scene.meshes.size() - 1)));
    }
    const testing::ReyesFrame frame = render_reyes(scene, camera, {.pixel_samples = 4});
    const double exposure = camera.exposure_scale();
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const Rgb c = frame.film.pixel({x, y});
        EXPECT_NEAR(c.r / exposure, 0.5, 1.0 / 255);
        EXPECT_NEAR(c.g / exposure, 0.25, 1.0 / 255);
        EXPECT_NEAR(c.b / exposure, 0.125, 1.0 / 255);
      }
    const Image sums = frame.film.sums();
    if (!first) first = sums;
    EXPECT_EQ(std::memcmp(first->data.data(), sums.data.data(), sums.data.size() * sizeof(float)),
              0);
  } while (std::next_permutation(order.begin(), order.end()));
}

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

// A lit, depth-of-field, motion-blurred frame: the same bits for 1 or 2 threads, buckets of 8, 16
// or 32 pixels, a frame rendered in 3 parts, and a crop window's region.
TEST(ReyesVisibility, IsBitIdenticalAcrossThreadsBucketsAndParts) {
  Scene scene = sphere_scene();
  scene.instances[0].motion = {{0, Transform()}, {1.0 / 60, Transform::translate({0.2, 0, 0})}};
  scene.camera.film.width_px = scene.camera.film.height_px = 96;
  scene.camera.lens.depth_of_field = true;
  scene.camera.lens.f_number = 2.8;
  scene.camera.lens.focus_distance_m = 4;
  FrameSettings settings{.renderer = renderer_named("reyes"), .samples_per_pixel = 1};
  settings.reyes.pixel_samples = 4;
  std::optional<Image> reference;
  for (int threads : {1, 2})
    for (int bucket : {8, 16, 32}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
      settings.reyes.bucket_size = bucket;
      const RenderedFrame frame = render_frame(scene, scene.camera, settings, false);
      if (!reference) reference = frame.film_sums;
      EXPECT_TRUE(same_bits(frame.film_sums, *reference)) << threads << " threads, " << bucket;
    }
  const int kParts = 3;
  const TileDeal deal{.width = 96, .height = 96, .tile_size = reyes::kTileSize, .parts = kParts};
  Image sums(96, 96, reference->channels);
  for (int part = 0; part < kParts; ++part) {
    settings.share = {.part = part, .parts = kParts, .settle = {}};
    const RenderedFrame frame = render_frame(scene, scene.camera, settings, false);
    unpack_owned_pixels(deal, part, pack_owned_pixels(deal, part, frame.film_sums), sums);
  }
  EXPECT_TRUE(same_bits(sums, *reference));
  // A crop window renders exactly its region of the whole frame.
  settings.share = {};
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

}  // namespace
}  // namespace obscura
