// A renderer added in one file: a back end (render/renderer_backend.h) that shades every camera
// ray by its direction — a sky gradient — drawn with the frame control every renderer shares
// (camera/camera_sample.h, film/pass_schedule.h, the WorkShare's tiles). Through that seam alone
// it gets what Obscura's renderers get: sessions that keep its compilation, finishing (glare),
// frames split into parts that assemble bit for bit, time limits, and refusals of what its
// capabilities row does not offer. Its pixels are checked against the gradient computed here
// from the pinhole geometry, not from the camera code.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <numbers>

#include "obscura/camera/camera_sample.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/film/pass_schedule.h"
#include "obscura/math/error.h"
#include "obscura/render/ground_truth_frame.h"
#include "obscura/render/render_session.h"
#include "obscura/render/renderer_backend.h"
#include "trace/trace_test_scenes.h"

namespace obscura {
namespace {

constexpr int kSize = 24;
constexpr double kHfovDegrees = 50;

// The sky: radiance rising with the ray's height, (1, 0.8, 0.6) × (0.5 + 0.5 y).
Rgb sky(Vector3d direction) {
  const float up = float(0.5 + 0.5 * direction.y);
  return Rgb(1.0f, 0.8f, 0.6f) * up;
}

class SkyScene final : public CompiledScene {
 public:
  explicit SkyScene(int* compilations) { ++*compilations; }
  bool serves(const Shutter&) const override { return true; }  // nothing in a sky moves
};

// The whole renderer.
class SkyBackend final : public RendererBackend {
 public:
  SkyBackend()
      : RendererBackend("sky", "the sky gradient, for tests",
                        {.takes_samples_per_pixel = true, .tile_size = 8}) {}

  std::unique_ptr<CompiledScene> compile(const Scene&, const Shutter&) const override {
    return std::make_unique<SkyScene>(&compilations);
  }

  FrameStats render(const CompiledScene&, const Camera& camera, const FrameSettings& settings,
                    Film& film, AovBuffers* aovs, const ProgressCallback& progress) const override {
    const PreparedCamera prepared = camera.prepare();
    const CameraSampleOrder order(camera, false, false);
    std::vector<Bounds2i> tiles;
    const std::vector<Bounds2i> all = make_tiles(film.bounds(), capabilities().tile_size);
    for (size_t t = 0; t < all.size(); ++t)
      if (settings.share.owns_tile(int(t))) tiles.push_back(all[t]);
    PassSchedule passes(settings.samples_per_pixel, 64, OnCancel::kAbandonPass,
                        {settings.time_limit_s, settings.cancel, &settings.share});
    Pass pass;
    while (passes.next(pass)) {
      for_each_tile_parallel(
          tiles,
          [&](const Bounds2i& tile) {
            for (int y = tile.min.y; y < tile.max.y; ++y)
              for (int x = tile.min.x; x < tile.max.x; ++x)
                for (int s = pass.first; s < pass.end; ++s) {
                  Sampler sampler(settings.sampler, settings.seed, {x, y}, uint32_t(s));
                  const CameraSample cs = order.draw(sampler, {x, y}, order.pixel_delay_s({x, y}));
                  const auto ray =
                      prepared.generate_ray(cs.film_point, {cs.lens.x, cs.lens.y}, cs.time_s);
                  film.add_sample({x, y}, ray ? sky(ray->direction) : Rgb(),
                                  float(cs.filter_weight));
                  if (aovs) aovs->add_sample({x, y}, false, {}, {}, 0, 0, 0);
                }
          },
          [&](int done, int count) { passes.report(progress, pass, done, count); });
      passes.finish(pass);
    }
    FrameStats stats;
    stats.seconds = passes.seconds();
    stats.done = passes.done();
    stats.requested = settings.samples_per_pixel;
    stats.cancelled = passes.cancelled();
    stats.time_limited = passes.time_limited();
    return stats;
  }

  mutable int compilations = 0;
};

Scene sky_scene() {
  Scene scene;
  scene.camera = testing::make_camera({0, 0, 0}, {0, 0, -1}, kSize, kHfovDegrees);
  scene.camera.film.filter = BoxFilter{1e-6};  // every sample at its pixel's centre
  return scene;
}

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

TEST(FakeRenderer, RendersTheSkyThroughTheSharedFrameControl) {
  const SkyBackend backend;
  const Scene scene = sky_scene();
  const FrameSettings settings{.renderer = Renderer(backend), .samples_per_pixel = 4};
  const Image image = render_frame(scene, scene.camera, settings, false).finished();
  // The pixel centre's ray, from the pinhole's geometry: (u, v, −1) normalized.
  const double t = std::tan(kHfovDegrees / 2 * std::numbers::pi / 180);
  double worst = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double u = t * (2 * (x + 0.5) / kSize - 1), v = t * (1 - 2 * (y + 0.5) / kSize);
      const Rgb expected = sky(Vector3d(u, v, -1) / std::sqrt(u * u + v * v + 1));
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(image.at(x, y, c)) - expected[c]));
    }
  EXPECT_LT(worst, 1e-5);
}

TEST(FakeRenderer, ASessionCompilesItOnceAndFinishingAppliesToIt) {
  const SkyBackend backend;
  const Scene scene = sky_scene();
  RenderSession session(scene);
  FrameSettings settings{.renderer = Renderer(backend), .samples_per_pixel = 2};
  const RenderedFrame plain = session.render(scene.camera, settings, true);
  settings.glare = GlareSettings{.strength = 1, .radius_px = 8};
  const RenderedFrame glared = session.render(scene.camera, settings, true);
  EXPECT_EQ(backend.compilations, 1);
  EXPECT_EQ(session.compilations(), 1);
  EXPECT_EQ(plain.stats.done, 2);
  ASSERT_TRUE(glared.finish.glare);
  EXPECT_TRUE(same_bits(glared.film_sums, plain.film_sums));     // the film is the renderer's
  EXPECT_FALSE(same_bits(glared.finished(), plain.finished()));  // the frame is finished
}

TEST(FakeRenderer, PartsOfAFrameAssembleIntoTheLoneFrameBitForBit) {
  const SkyBackend backend;
  const Scene scene = sky_scene();
  FrameSettings settings{.renderer = Renderer(backend), .samples_per_pixel = 3};
  const RenderedFrame lone = render_frame(scene, scene.camera, settings, false);
  for (int parts : {2, 3, 7}) {
    const TileDeal deal{.width = kSize,
                        .height = kSize,
                        .tile_size = backend.capabilities().tile_size,
                        .parts = parts};
    Image sums(kSize, kSize, lone.film_sums.channels);
    int settles = 0;
    for (int part = 0; part < parts; ++part) {
      settings.share = {.part = part, .parts = parts, .settle = [&](StopVerdict own) {
                          ++settles;
                          return own;
                        }};
      const RenderedFrame frame = render_frame(scene, scene.camera, settings, false);
      unpack_owned_pixels(deal, part, pack_owned_pixels(deal, part, frame.film_sums), sums);
    }
    EXPECT_EQ(settles, parts * 3);  // passes of 1, 1 and 1 sample on every part
    EXPECT_TRUE(same_bits(sums, lone.film_sums)) << parts << " parts";
  }
}

TEST(FakeRenderer, WhatItsCapabilitiesLackIsRefused) {
  const SkyBackend backend;
  const Scene scene = sky_scene();
  EXPECT_THROW(
      render_frame(scene, scene.camera, {.renderer = Renderer(backend), .spectral = true}, false),
      Error);
  EXPECT_THROW(render_ground_truth_frame(scene, scene.camera, {.renderer = Renderer(backend)},
                                         default_ground_truth_times(scene.camera)),
               Error);
  EXPECT_FALSE(parse_renderer("sky"));  // not in the command line's table: a test's own
}

}  // namespace
}  // namespace obscura
