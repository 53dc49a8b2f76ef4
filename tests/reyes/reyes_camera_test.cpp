// REYES's camera effects and dicing against independent references: the blur ramp of a moving
// edge against its speed, the bokeh of a tiny emitter against the thin lens's circle of
// confusion, one shading pass with or without those effects, micropolygon size against the
// shading rate, shading against the rasterizer's, and the knobs' refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "obscura/math/error.h"
#include "obscura/render/frame_settings.h"
#include "obscura/render/render_frame.h"
#include "obscura/render/renderer.h"
#include "reyes/reyes_test_scenes.h"

namespace obscura {
namespace {

using testing::render_reyes;

// A half-plane (x < 0) moving right by `v` pixels over the shutter, seen orthographically: the
// mean profile across the edge is the uniform distribution of the edge over v pixels, blurred by
// the pixel, so the spread of its derivative (adjacent-pixel differences) has variance
// v²/12 + 1/6 (the box convolved with itself), from which v is measured back.
struct MovingEdge {
  Scene scene;
  Camera camera;
  int width = 0;
};

MovingEdge moving_edge(double v) {
  constexpr int kHeight = 64;
  MovingEdge e;
  e.width = int(v) + 48;
  const double pixel_m = 0.01;
  e.scene.materials = {testing::unlit_material(Rgb(1.f))};
  e.scene.meshes.push_back(
      testing::make_quad("half", 0, {-100, -10, 0}, {0, -10, 0}, {0, 10, 0}, {-100, 10, 0}));
  const double start = -(v / 2) * pixel_m;  // centred in the image over the shutter
  Instance moving = testing::make_instance("half", 0);
  moving.world_from_object = Transform::translate({start, 0, 0});
  moving.motion = {{0, Transform::translate({start, 0, 0})},
                   {1.0 / 60, Transform::translate({start + v * pixel_m, 0, 0})}};
  e.scene.instances = {moving};
  e.camera = testing::orthographic_camera(kHeight * pixel_m, e.width, kHeight);
  return e;
}

double measured_blur_px(double v) {
  constexpr int kHeight = 64;
  const MovingEdge edge = moving_edge(v);
  const Scene& scene = edge.scene;
  const Camera& camera = edge.camera;
  const int width = edge.width;
  const testing::ReyesFrame frame = render_reyes(scene, camera, {.pixel_samples = 64});
  std::vector<double> profile(size_t(width), 0.0);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < width; ++x)
      profile[size_t(x)] += testing::coverage(frame, camera, x, y) / kHeight;
  double mass = 0, mean = 0, second = 0;
  for (int x = 0; x + 1 < width; ++x) {
    const double d = profile[size_t(x)] - profile[size_t(x) + 1];
    mass += d, mean += d * (x + 1), second += d * (x + 1) * (x + 1);
  }
  mean /= mass;
  const double variance = second / mass - mean * mean;
  return std::sqrt(12 * (variance - 1.0 / 6));
}

TEST(ReyesCamera, AMovingEdgeRampsOverItsSpeed) {
  for (double v : {4.0, 16.0, 64.0}) EXPECT_NEAR(measured_blur_px(v), v, 0.5) << v << " px";
}

// The same camera numbers (film point, lens point, time) for the same seed in both renderers:
// each sample sees the same surface, so the moving edge's pixels agree with the tracer's to a
// sample, and almost all of them exactly.
TEST(ReyesCamera, BlursAsTheTracerDoesSampleForSample) {
  const MovingEdge edge = moving_edge(16);
  FrameSettings settings{.renderer = renderer_named("direct"), .samples_per_pixel = 16};
  settings.reyes.pixel_samples = 16;
  const Image traced = render_frame(edge.scene, edge.camera, settings, false).finished();
  settings.renderer = renderer_named("reyes");
  const Image reyes = render_frame(edge.scene, edge.camera, settings, false).finished();
  const double one_sample = edge.camera.exposure_scale() / 16;
  int differ = 0, ramp = 0;
  for (int y = 0; y < traced.height; ++y)
    for (int x = 0; x < traced.width; ++x) {
      const double d = std::abs(double(reyes.at(x, y, 0)) - traced.at(x, y, 0));
      EXPECT_LE(d, one_sample * 1.001);
      differ += d > 1e-6;
      ramp += traced.at(x, y, 0) > 0 && traced.at(x, y, 0) < edge.camera.exposure_scale();
    }
  EXPECT_GT(ramp, 12 * 64);
  std::printf("moving edge: %d of %d pixels differ from the tracer's (%d blurred)\n", differ,
              traced.width * traced.height, ramp);
  EXPECT_LE(differ, traced.width * traced.height / 100);
}

// Depth of field likewise: a small square off the focus plane through a bladed f/1.4 lens, each
// sample's lens point the tracer's, so the bokeh (the blade polygon included) agrees with the
// tracer's sample for sample.
TEST(ReyesCamera, DefocusesAsTheTracerDoesSampleForSample) {
  constexpr int kSize = 128;
  Camera camera = testing::make_camera({0, 0, 0}, {0, 0, -1}, kSize, 30);
  camera.film.filter = BoxFilter{0.5};
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 1.4;
  camera.lens.focus_distance_m = 1.5;
  camera.lens.aperture.blades = 6;
  const float h = 0.004f, z = -0.6f;  // nearer than the focus: a bokeh ~12 px across
  Scene scene;
  scene.materials = {testing::unlit_material(Rgb(1.f))};
  scene.meshes.push_back(
      testing::make_quad("dot", 0, {-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}));
  scene.instances = {testing::make_instance("dot", 0)};
  FrameSettings settings{.renderer = renderer_named("direct"), .samples_per_pixel = 16};
  settings.reyes.pixel_samples = 16;
  const Image traced = render_frame(scene, camera, settings, false).finished();
  settings.renderer = renderer_named("reyes");
  const Image reyes = render_frame(scene, camera, settings, false).finished();
  const double one_sample = camera.exposure_scale() / 16;
  int differ = 0, lit = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double d = std::abs(double(reyes.at(x, y, 0)) - traced.at(x, y, 0));
      EXPECT_LE(d, one_sample * 1.001);
      differ += d > 1e-6;
      lit += traced.at(x, y, 0) > 0;
    }
  std::printf("bokeh: %d of %d lit pixels differ from the tracer's\n", differ, lit);
  EXPECT_GT(lit, 100);
  EXPECT_LE(differ, lit / 100 + 1);
}

// A small white square (3 px) off the focus plane images as the aperture: its spread (second
// moment of a uniform disk of diameter D: D²/8, plus the pixel's 1/6 and the square's own
// 3²/6) gives D back, compared with the thin lens's circle of confusion at its depth.
TEST(ReyesCamera, ASmallEmitterBlursIntoTheCircleOfConfusion) {
  constexpr int kSize = 256;
  constexpr double kSide = 3;  // pixels
  for (double depth : {0.8, 3.0, 20.0}) {
    Camera camera = testing::make_camera({0, 0, 0}, {0, 0, -1}, kSize, 30);
    camera.film.filter = BoxFilter{0.5};
    camera.lens.depth_of_field = true;
    camera.lens.f_number = 1.4;
    camera.lens.focus_distance_m = 1.5;
    const double pixel_at_depth = 2 * depth * std::tan(15 * std::numbers::pi / 180) / kSize;
    const float h = float(kSide * pixel_at_depth / 2);
    const float z = float(-depth);
    Scene scene;
    scene.materials = {testing::unlit_material(Rgb(1.f))};
    scene.meshes.push_back(
        testing::make_quad("dot", 0, {-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}));
    scene.instances = {testing::make_instance("dot", 0)};
    const testing::ReyesFrame frame = render_reyes(scene, camera, {.pixel_samples = 128});
    double mass = 0, mx = 0, my = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double c = frame.film.pixel({x, y}).r;
        mass += c, mx += c * (x + 0.5), my += c * (y + 0.5);
      }
    mx /= mass, my /= mass;
    double r2 = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double dx = x + 0.5 - mx, dy = y + 0.5 - my;
        r2 += frame.film.pixel({x, y}).r * (dx * dx + dy * dy);
      }
    r2 /= mass;
    const double diameter = std::sqrt(8 * (r2 - 1.0 / 6 - kSide * kSide / 6));
    const double expected = camera.circle_of_confusion_px(depth);
    EXPECT_GT(expected, 6);
    EXPECT_NEAR(diameter, expected, 1.0) << "at " << depth << " m";
  }
}

Scene lit_sphere(bool moving) {
  Scene scene;
  scene.materials = {diffuse_material("grey", Rgb(0.7f))};
  scene.meshes.push_back(testing::make_sphere({0, 0, 0}, 1, 0, 24, 48));
  Instance sphere = testing::make_instance("sphere", 0);
  if (moving)
    sphere.motion = {{0, Transform::translate({-0.1, 0, 0})},
                     {1.0 / 60, Transform::translate({0.1, 0, 0})}};
  scene.instances = {sphere};
  scene.lights.push_back(
      testing::make_light("key", PointLight{.position = {3, 4, 5}, .intensity = Rgb(40.f)}));
  scene.camera = testing::make_camera({0, 0, 5}, {0, 0, 0}, 128, 40);
  return scene;
}

// A lit disk facing the camera, moving across or still: nothing hides anything, so occlusion
// culling (which depends on what the samples see) plays no part in what is shaded.
Scene lit_disk(bool moving) {
  Scene scene = lit_sphere(moving);
  scene.meshes[0] = testing::make_disk(1, 0, 64, 0);
  return scene;
}

// Motion blur and depth of field cost visibility samples, not shading.
TEST(ReyesCamera, ShadesEveryVertexOnceWithOrWithoutMotionBlurAndDefocus) {
  const reyes::ReyesSettings settings{.pixel_samples = 4};
  const Scene still = lit_disk(false);
  const uint64_t shaded = render_reyes(still, still.camera, settings).stats.shaded_vertices;
  EXPECT_GT(shaded, 1000u);
  const Scene moving = lit_disk(true);
  EXPECT_EQ(render_reyes(moving, moving.camera, settings).stats.shaded_vertices, shaded);
  Camera defocused = moving.camera;
  defocused.lens.depth_of_field = true;
  defocused.lens.f_number = 2;
  defocused.lens.focus_distance_m = 3;
  const testing::ReyesFrame both = render_reyes(moving, defocused, settings);
  EXPECT_EQ(both.stats.shaded_vertices, shaded);
  EXPECT_GT(both.stats.samples_tested,
            render_reyes(still, still.camera, settings).stats.samples_tested);
}

// A plane filling a perspective view: no micropolygon larger than the rate; their number
// inversely proportional to it.
TEST(ReyesCamera, DicesMicropolygonsToTheShadingRate) {
  Scene scene;
  scene.materials = {testing::unlit_material(Rgb(1.f))};
  scene.meshes.push_back(
      testing::make_quad("floor", 0, {-4, -1, 2}, {4, -1, 2}, {4, -1, -12}, {-4, -1, -12}));
  scene.instances = {testing::make_instance("floor", 0)};
  const Camera camera = testing::make_camera({0, 0.5, 3}, {0, -0.5, -2}, 200, 60);
  double previous = 0;
  for (double rate : {1.0, 4.0, 16.0}) {
    const reyes::ReyesStats stats =
        render_reyes(scene, camera, {.shading_rate = rate, .pixel_samples = 1}).stats;
    EXPECT_LE(stats.area_max_px, rate * (1 + 1e-9)) << rate;
    EXPECT_GT(stats.area_mean_px, rate / 16) << rate;  // not wastefully fine
    if (previous > 0) {
      const double ratio = previous / double(stats.micropolygons);
      EXPECT_GT(ratio, 4 * 0.75) << rate;
      EXPECT_LT(ratio, 4 * 1.25) << rate;
    }
    previous = double(stats.micropolygons);
  }
}

// The same scene and formulas through the rasterizer (per-pixel shading at the pixel centre) and
// REYES (shaded at micropolygon vertices): within 1 % inside the sphere.
TEST(ReyesCamera, ShadesAsTheRasterizerDoes) {
  Scene scene = lit_sphere(false);
  PhongMaterial phong;
  phong.diffuse = {0.5f, 0.4f, 0.3f};
  phong.specular = Rgb(0.2f);
  phong.shininess = 20;
  scene.materials[0].model = phong;
  scene.lights.push_back(testing::make_light(
      "sun", DirectionalLight{.direction = {-0.3f, -1, -0.5f}, .irradiance = Rgb(1.f)}));
  scene.camera.film.filter = BoxFilter{1e-6};
  FrameSettings raster{.renderer = renderer_named("raster")};
  raster.raster.shadow_map_size = 0;
  const RenderedFrame r = render_frame(scene, scene.camera, raster, true);
  FrameSettings reyes{.renderer = renderer_named("reyes")};
  reyes.reyes.pixel_samples = 1;
  const RenderedFrame q = render_frame(scene, scene.camera, reyes, true);
  const Image a = r.finished(), b = q.finished(), ids = r.aovs->id();
  double sum = 0;
  int count = 0;
  for (int y = 1; y + 1 < a.height; ++y)
    for (int x = 1; x + 1 < a.width; ++x) {
      bool inside = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) inside = inside && ids.at(x + dx, y + dy, 0) == 0;
      if (!inside) continue;
      for (int c = 0; c < 3; ++c) {
        const double ref = a.at(x, y, c);
        if (ref < 1e-3) continue;
        sum += std::abs(b.at(x, y, c) - ref) / ref;
        ++count;
      }
    }
  ASSERT_GT(count, 3000);
  EXPECT_LT(sum / count, 0.01);
}

// A ground plane through the camera: eye-split a bounded number of times, the rest dropped with
// one warning; what is drawn agrees with the tracer's hits.
TEST(ReyesCamera, EyeSplitsAPlaneThroughTheCamera) {
  Scene scene;
  scene.materials = {testing::unlit_material(Rgb(1.f))};
  scene.meshes.push_back(
      testing::make_quad("ground", 0, {-50, -1, 50}, {50, -1, 50}, {50, -1, -50}, {-50, -1, -50}));
  scene.instances = {testing::make_instance("ground", 0)};
  Camera camera = testing::make_camera({0, 0, 0}, {0, -0.3, -1}, 96, 70);
  camera.film.filter = BoxFilter{1e-6};
  FrameSettings settings{.renderer = renderer_named("reyes"), .samples_per_pixel = 1};
  settings.reyes.pixel_samples = 1;
  const RenderedFrame reyes = render_frame(scene, camera, settings, true);
  settings.renderer = renderer_named("direct");
  const RenderedFrame traced = render_frame(scene, camera, settings, true);
  const Image a = reyes.aovs->id(), b = traced.aovs->id();
  int differ = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) differ += a.at(x, y, 0) != b.at(x, y, 0);
  EXPECT_LE(differ, 96 * 96 / 1000);
  bool split = false;
  for (const std::string& line : reyes.stats.details)
    split = split || (line.rfind("reyes eye splits: ", 0) == 0 && line != "reyes eye splits: 0");
  EXPECT_TRUE(split);
}

TEST(ReyesCamera, RefusesAbsurdKnobsNamingThem) {
  const Scene scene = lit_sphere(false);
  auto refused = [&](reyes::ReyesSettings s, const std::string& option) {
    try {
      render_reyes(scene, scene.camera, s);
    } catch (const Error& e) {
      return std::string(e.what()).find(option) != std::string::npos;
    }
    return false;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double rate : {0.0, 1e-9, 1e9, nan, -1.0})
    EXPECT_TRUE(refused({.shading_rate = rate}, "--reyes-shading-rate")) << rate;
  EXPECT_TRUE(refused({.grid_size = 0}, "--reyes-grid-size"));
  EXPECT_TRUE(refused({.grid_size = 1 << 30}, "--reyes-grid-size"));
  EXPECT_TRUE(refused({.bucket_size = 0}, "--reyes-bucket-size"));
  EXPECT_TRUE(refused({.bucket_size = 1000}, "--reyes-bucket-size"));
  EXPECT_TRUE(refused({.pixel_samples = 0}, "--reyes-pixel-samples"));
  EXPECT_TRUE(refused({.pixel_samples = 1 << 20}, "--reyes-pixel-samples"));
  EXPECT_TRUE(refused({.eye_splits = -1}, "--reyes-eye-splits"));
}

}  // namespace
}  // namespace obscura
