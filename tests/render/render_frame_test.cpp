// The library's entry points (render/render_frame.h, raster/render.h) without the command line:
// - render_frame is bit-identical to calling the tracer's render and raster::render directly;
// - both renderers fill the one AOV model, with the distance along each pixel centre's ray equal
//   to the analytic distance to a plane, its normal and its id;
// - tracer and rasterizer agree on a diffuse plane under a uniform sky (radiance ρ·L);
// - the rasterizer's effects: accumulation with depth of field off is one frame bit for bit;
//   motion blur keeps the object's energy and smears its edges over the distance it moves;
//   post-process depth of field on a frame in parts, assembled, is the lone frame bit for bit.
#include "obscura/render/render_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "obscura/film/image_metrics.h"
#include "obscura/film/work_share.h"
#include "obscura/math/error.h"
#include "obscura/raster/render.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "trace/trace_test_scenes.h"

namespace obscura {
namespace {

constexpr int kSize = 32;
constexpr double kHfovDegrees = 40;
constexpr float kPlaneDistance = 3;
constexpr float kReflectance = 0.5f;

// A camera at the origin looking down −Z at a large grey diffuse plane z = −3 under a uniform
// sky of radiance 1; pixel samples at the pixel centres.
Scene plane_scene() {
  Scene scene;
  Material grey;
  grey.name = "grey";
  DiffuseMaterial diffuse;
  diffuse.reflectance = Rgb(kReflectance);
  grey.model = diffuse;
  scene.materials = {grey};
  const float z = -kPlaneDistance, r = 100;
  scene.add_mesh(testing::make_quad("plane", 0, {-r, -r, z}, {r, -r, z}, {r, r, z}, {-r, r, z}));
  scene.environment = Environment{};
  scene.camera = testing::make_camera({0, 0, 0}, {0, 0, -1}, kSize, kHfovDegrees);
  scene.camera.film.filter = BoxFilter{1e-6};
  return scene;
}

// The distance from the eye to the plane along pixel (x, y)'s centre ray.
double plane_distance(int x, int y) {
  const double t = std::tan(kHfovDegrees / 2 * std::numbers::pi / 180);
  const double u = t * (2 * (x + 0.5) / kSize - 1), v = t * (1 - 2 * (y + 0.5) / kSize);
  return kPlaneDistance * std::sqrt(1 + u * u + v * v);
}

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels && a.data == b.data;
}

double mean_green(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, 1);
  return sum / (double(image.width) * image.height);
}

TEST(RenderFrame, RenderersAreParsedByName) {
  std::vector<std::string> names;
  for (Renderer r : renderers()) {
    EXPECT_EQ(parse_renderer(r.name()), r);
    names.push_back(r.name());
  }
  EXPECT_EQ(names, (std::vector<std::string>{"path", "whitted", "direct", "raster", "reyes"}));
  EXPECT_EQ(Renderer(), renderer_named("path"));  // the default
  EXPECT_EQ(renderer_names(), "path, whitted, direct, raster or reyes");
  EXPECT_FALSE(parse_renderer("Path"));
  EXPECT_FALSE(parse_renderer(""));
  EXPECT_THROW(renderer_named("Reyes"), Error);
  EXPECT_EQ(renderer_named("path").capabilities().tile_size, 16);
  EXPECT_EQ(renderer_named("raster").capabilities().tile_size, 64);
  EXPECT_EQ(renderer_named("reyes").capabilities().tile_size, 64);
  EXPECT_TRUE(renderer_named("path").capabilities().spectral);
  EXPECT_FALSE(renderer_named("whitted").capabilities().spectral);
}

TEST(RenderFrame, TracerIsObscuraRenderBitForBit) {
  const Scene scene = plane_scene();
  FrameSettings settings{.renderer = renderer_named("path"), .samples_per_pixel = 4, .seed = 7};
  Film film(kSize, kSize);
  AovBuffers aovs(kSize, kSize);
  FrameStats stats = render_frame(scene, scene.camera, settings, film, &aovs);
  EXPECT_EQ(stats.done, 4);
  EXPECT_EQ(stats.requested, 4);
  EXPECT_GT(stats.rays, 0);
  EXPECT_FALSE(stats.partial());

  TraceScene trace_scene(scene, testing::embree_device());
  Film direct(kSize, kSize);
  AovBuffers direct_aovs(kSize, kSize);
  render(trace_scene, scene.camera, PathTracer(), {.samples_per_pixel = 4, .seed = 7}, direct, {},
         &direct_aovs);
  EXPECT_TRUE(same_bits(film.sums(), direct.sums()));
  for (size_t i = 0; i < aovs.images().size(); ++i)
    EXPECT_TRUE(same_bits(aovs.images()[i].image, direct_aovs.images()[i].image));
}

TEST(RenderFrame, RasterIsRasterRenderBitForBit) {
  const Scene scene = plane_scene();
  FrameSettings settings{.renderer = renderer_named("raster"), .seed = 5};
  settings.raster.msaa_samples = 4;
  Film film(kSize, kSize);
  AovBuffers aovs(kSize, kSize);
  FrameStats stats = render_frame(scene, scene.camera, settings, film, &aovs);
  EXPECT_EQ(stats.done, 1);

  raster::RenderSettings direct_settings;
  direct_settings.msaa_samples = 4;
  direct_settings.seed = 5;
  Film direct(kSize, kSize);
  AovBuffers direct_aovs(kSize, kSize);
  raster::render(scene, scene.camera, direct_settings, direct, &direct_aovs);
  EXPECT_TRUE(same_bits(film.sums(), direct.sums()));
  ASSERT_EQ(aovs.images().size(), 4u);  // no albedo from the rasterizer
  for (size_t i = 0; i < 4; ++i)
    EXPECT_TRUE(same_bits(aovs.images()[i].image, direct_aovs.images()[i].image));
}

TEST(RenderFrame, BothRenderersFillTheAovsWithThePlanesDepthRangeNormalAndId) {
  const Scene scene = plane_scene();
  for (Renderer renderer : {renderer_named("path"), renderer_named("raster")}) {
    SCOPED_TRACE(renderer.name());
    FrameSettings settings{.renderer = renderer, .samples_per_pixel = 2};
    Film film(kSize, kSize);
    AovBuffers aovs(kSize, kSize);
    render_frame(scene, scene.camera, settings, film, &aovs);
    EXPECT_EQ(aovs.has_albedo(), renderer != renderer_named("raster"));
    const Image depth = aovs.depth(), range = aovs.range(), normal = aovs.normal(), id = aovs.id(),
                albedo = aovs.albedo();
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        // depth along the optical axis: the plane faces the camera, so every pixel's is its
        // distance; range along the pixel centre's ray.
        ASSERT_NEAR(depth.at(x, y, 0), kPlaneDistance, 2e-4 * kPlaneDistance) << x << "," << y;
        ASSERT_NEAR(range.at(x, y, 0), plane_distance(x, y), 2e-4 * plane_distance(x, y))
            << x << "," << y;
        ASSERT_NEAR(normal.at(x, y, 2), 1, 1e-5);
        ASSERT_EQ(id.at(x, y, 0), 0);
        if (aovs.has_albedo()) {
          ASSERT_NEAR(albedo.at(x, y, 1), kReflectance, 1e-6);
        }
      }
  }
}

TEST(RenderFrame, TracerAndRasterizerAgreeOnADiffusePlaneUnderAUniformSky) {
  // A plane of reflectance ρ under radiance 1 from the whole hemisphere reflects ρ·1.
  const Scene scene = plane_scene();
  double means[2];
  int i = 0;
  for (Renderer renderer : {renderer_named("path"), renderer_named("raster")}) {
    Film film(kSize, kSize);
    render_frame(scene, scene.camera, {.renderer = renderer, .samples_per_pixel = 64, .seed = 1},
                 film);
    means[i++] = mean_green(film.to_image());
  }
  EXPECT_NEAR(means[0], kReflectance, 0.01 * kReflectance);
  EXPECT_NEAR(means[1], kReflectance, 0.02 * kReflectance);
  EXPECT_NEAR(means[1], means[0], 0.02 * kReflectance);
}

// A 0.5 m square in front of the plane at 2 m: an edge to blur.
Scene square_scene() {
  Scene scene = plane_scene();
  scene.environment.reset();  // black where nothing is, so the square alone carries light
  scene.instances.clear();
  scene.meshes.clear();
  Material white;
  white.name = "white";
  white.emission = Rgb(1.f);
  white.model = EmissiveMaterial{};
  scene.materials = {white};
  const float z = -2, h = 0.25f;
  scene.add_mesh(testing::make_quad("square", 0, {-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}));
  return scene;
}

// The square's side in pixels: 0.5 m at 2 m across a 40° field of 32 pixels (≈ 11).
double square_side_px() {
  return 0.5 / (2 * std::tan(kHfovDegrees / 2 * std::numbers::pi / 180)) * (kSize / 2.0);
}

// Depth of field focused at 0.6 m, wide open: the square at 2 m is blurred by a circle of
// confusion of about 3 pixels. Without focus breathing the framing is the pinhole's.
void open_lens(Camera& camera) {
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 1;
  camera.lens.focus_distance_m = 0.6;
  camera.lens.focus_breathing = false;
}

TEST(RenderFrame, AccumulationWithDepthOfFieldOffIsOneFrameBitForBit) {
  Scene scene = square_scene();
  raster::RenderSettings msaa;
  msaa.msaa_samples = 8;
  Film sharp(kSize, kSize);
  raster::RenderStats one = raster::render(scene, scene.camera, msaa, sharp);
  EXPECT_EQ(one.frames, 1);

  open_lens(scene.camera);
  raster::RenderSettings off = msaa;
  off.depth_of_field = raster::DepthOfFieldMethod::kOff;
  off.effect_samples = 16;
  Film film(kSize, kSize);
  raster::RenderStats stats = raster::render(scene, scene.camera, off, film);
  EXPECT_EQ(stats.frames, 1);
  EXPECT_TRUE(same_bits(film.sums(), sharp.sums()));

  // Accumulated, the out-of-focus square spreads its edge but keeps its light.
  raster::RenderSettings accumulate = msaa;
  accumulate.effect_samples = 16;
  Film blurred(kSize, kSize);
  stats = raster::render(scene, scene.camera, accumulate, blurred);
  EXPECT_EQ(stats.frames, 16);
  EXPECT_FALSE(same_bits(blurred.sums(), sharp.sums()));
  const double area = square_side_px() * square_side_px();
  EXPECT_NEAR(mean_green(sharp.to_image()) * kSize * kSize, area, 0.04 * area);
  EXPECT_NEAR(mean_green(blurred.to_image()) * kSize * kSize, area, 0.04 * area);
}

TEST(RenderFrame, MotionBlurKeepsTheLightAndSmearsTheEdgesOverTheMotion) {
  Scene scene = square_scene();
  // The square slides 0.3 m to the right while the shutter is open: 0.6 of its side.
  scene.camera.shutter = {.open_s = 0, .close_s = 1};
  scene.instances[0].motion = {{0.0, Transform()}, {1.0, Transform::translate({0.3, 0, 0})}};
  const double moved_px = 0.6 * square_side_px();
  Film film(kSize, kSize);
  raster::RenderSettings settings;
  settings.msaa_samples = 8;
  settings.effect_samples = 64;
  raster::RenderStats stats = raster::render(scene, scene.camera, settings, film);
  EXPECT_EQ(stats.frames, 64);
  const Image image = film.to_image();

  // The light: the square covers as many pixels at every time.
  const double area = square_side_px() * square_side_px();
  EXPECT_NEAR(mean_green(image) * kSize * kSize, area, 0.04 * area);
  // Along the middle row, pixels neither black nor white lie where the edges swept.
  int partial = 0;
  for (int x = 0; x < kSize; ++x) {
    const float g = image.at(x, kSize / 2, 1);
    partial += g > 0.01f && g < 0.99f;
  }
  EXPECT_NEAR(partial, 2 * moved_px, 3);
}

// Part `part` of `parts` of a frame, put into `whole`.
void take_part(const TileDeal& deal, int part, const Image& from, Image& whole) {
  unpack_owned_pixels(deal, part, pack_owned_pixels(deal, part, from), whole);
}

TEST(RenderFrame, PostProcessDepthOfFieldInPartsIsTheLoneFrameOnceAssembled) {
  Scene scene = square_scene();
  open_lens(scene.camera);
  FrameSettings settings{.renderer = renderer_named("raster")};
  settings.raster.depth_of_field = raster::DepthOfFieldMethod::kPost;

  const RenderedFrame lone = render_frame(scene, scene.camera, settings, false);
  ASSERT_TRUE(lone.finish.depth_of_field);  // finished later, on the whole frame
  ASSERT_EQ(lone.layers.size(), 1u);

  Image sums(kSize, kSize, 4), layer(kSize, kSize, 2);
  for (int part = 0; part < 2; ++part) {
    settings.share = {.part = part, .parts = 2, .settle = {}};
    const RenderedFrame frame = render_frame(scene, scene.camera, settings, false);
    ASSERT_EQ(frame.layers.size(), 1u);
    const TileDeal raster_deal{.width = kSize,
                               .height = kSize,
                               .tile_size = renderer_named("raster").capabilities().tile_size,
                               .parts = 2};
    take_part(raster_deal, part, frame.film_sums, sums);
    take_part(raster_deal, part, frame.layers[0].image, layer);
  }
  const Image assembled =
      finish_frame(sums, {{std::string(kDepthOfFieldLayer), layer}}, lone.finish);
  EXPECT_TRUE(same_bits(assembled, lone.finished()));

  // And the post-process did blur: the out-of-focus square's edge is no longer hard.
  settings.share = {};
  settings.raster.depth_of_field = raster::DepthOfFieldMethod::kOff;
  const RenderedFrame sharp = render_frame(scene, scene.camera, settings, false);
  EXPECT_GT(rmse(lone.finished(), sharp.finished()), 0.01);
}

TEST(RenderFrame, BadSettingsAreErrorsNamingTheSetting) {
  const Scene scene = plane_scene();
  Film film(kSize, kSize);
  EXPECT_THROW(render_frame(scene, scene.camera, {.samples_per_pixel = 0}, film), Error);
  FrameSettings raster{.renderer = renderer_named("raster")};
  raster.raster.effect_samples = 0;
  EXPECT_THROW(render_frame(scene, scene.camera, raster, film), Error);
  Film wrong(kSize + 1, kSize);
  try {
    render_frame(scene, scene.camera, {.renderer = renderer_named("raster")}, wrong);
    FAIL() << "a film of another size was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("crop size"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace obscura
