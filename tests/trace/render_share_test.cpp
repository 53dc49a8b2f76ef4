// The tracer rendering a frame in parts (RenderSettings::share), as MPI ranks and --shard parts
// do: each part renders only its tiles, and the parts' pixels put together must be the lone
// render's bit for bit — film sums and AOVs — for any number of parts. The reference is always
// the same scene rendered by one process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/film/work_share.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "obscura/trace/whitted.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

constexpr int kWidth = 64, kHeight = 48;

// What one process's render leaves: the film's sums and the AOV images, and its stats.
struct PartImages {
  std::vector<Image> images;  // sums, albedo, normal, depth, range, id
  RenderStats stats;
};

const std::vector<std::string>& image_names() {
  static const std::vector<std::string> names = {"film sums", "albedo", "normal",
                                                 "depth",     "range",  "id"};
  return names;
}

Scene small_cornell_box() {
  Scene scene = load_scene("cornell-box");
  scene.camera.film.width_px = kWidth;
  scene.camera.film.height_px = kHeight;
  return scene;
}

struct CornellBox {
  Scene scene = small_cornell_box();
  TraceScene trace_scene{scene, testing::embree_device()};
};

const CornellBox& cornell_box() {
  static const CornellBox box;
  return box;
}

PartImages render_images(const Integrator& integrator, const RenderSettings& settings) {
  const CornellBox& box = cornell_box();
  Film film(kWidth, kHeight);
  AovBuffers aovs(kWidth, kHeight);
  PartImages part;
  part.stats = render(box.trace_scene, box.scene.camera, integrator, settings, film, {}, &aovs);
  part.images = {film.sums(), aovs.albedo(), aovs.normal(), aovs.depth(), aovs.range(), aovs.id()};
  return part;
}

// Assembles the parts' images as the team does: each part's owned pixels packed, then unpacked
// into one image per kind.
std::vector<Image> assemble(const std::vector<PartImages>& parts, int tile_size) {
  const TileDeal deal{
      .width = kWidth, .height = kHeight, .tile_size = tile_size, .parts = int(parts.size())};
  std::vector<Image> whole;
  for (const Image& image : parts.front().images)
    whole.emplace_back(image.width, image.height, image.channels);
  for (size_t p = 0; p < parts.size(); ++p)
    for (size_t i = 0; i < whole.size(); ++i)
      unpack_owned_pixels(deal, int(p), pack_owned_pixels(deal, int(p), parts[p].images[i]),
                          whole[i]);
  return whole;
}

void expect_identical(const Image& actual, const Image& expected, const std::string& what) {
  ASSERT_EQ(actual.width, expected.width) << what;
  ASSERT_EQ(actual.height, expected.height) << what;
  ASSERT_EQ(actual.channels, expected.channels) << what;
  if (std::memcmp(actual.data.data(), expected.data.data(), expected.data.size() * sizeof(float)) ==
      0)
    return;
  for (size_t i = 0; i < expected.data.size(); ++i)
    if (std::memcmp(&actual.data[i], &expected.data[i], sizeof(float)) != 0) {
      const size_t pixel = i / size_t(expected.channels);
      ADD_FAILURE() << what << ": first difference at pixel (" << pixel % size_t(expected.width)
                    << ", " << pixel / size_t(expected.width) << ") channel "
                    << i % size_t(expected.channels) << ": " << actual.data[i] << " vs "
                    << expected.data[i];
      return;
    }
}

// The number of passes a render of `spp` samples takes: 1, 1, 2, 4, … samples, at most 64 each,
// the last one cut to what is left (render.h).
int pass_count(int spp) {
  int passes = 0;
  for (int done = 0, size = 1; done < spp; ++passes) {
    done += std::min(size, spp - done);
    if (done > 1) size = std::min(64, size * 2);
  }
  return passes;
}

struct IntegratorCase {
  const char* name;
  std::shared_ptr<const Integrator> integrator;
};

std::vector<IntegratorCase> integrators() {
  return {{"path", std::make_shared<PathTracer>()},
          {"whitted", std::make_shared<WhittedIntegrator>()}};
}

TEST(RenderShare, PartsAssembleIntoTheLoneRenderBitForBit) {
  for (const IntegratorCase& c : integrators()) {
    SCOPED_TRACE(c.name);
    const RenderSettings lone_settings{.samples_per_pixel = 4, .seed = 7};
    const PartImages lone = render_images(*c.integrator, lone_settings);
    for (int parts : {2, 3, 5}) {
      SCOPED_TRACE(std::to_string(parts) + " parts");
      std::vector<PartImages> rendered;
      for (int part = 0; part < parts; ++part) {
        RenderSettings settings = lone_settings;
        settings.share = {.part = part, .parts = parts};
        rendered.push_back(render_images(*c.integrator, settings));
        EXPECT_EQ(rendered.back().stats.samples_per_pixel, 4);
        EXPECT_FALSE(rendered.back().stats.partial);
      }
      const std::vector<Image> whole = assemble(rendered, lone_settings.tile_size);
      for (size_t i = 0; i < whole.size(); ++i)
        expect_identical(whole[i], lone.images[i], image_names()[i]);
    }
  }
}

TEST(RenderShare, AnotherTileSizeDealsTheSameWay) {
  // The deal follows RenderSettings::tile_size: tiles of 7 pixels leave ragged edges.
  PathTracer tracer;
  const RenderSettings lone_settings{.samples_per_pixel = 2, .seed = 1, .tile_size = 7};
  const PartImages lone = render_images(tracer, lone_settings);
  std::vector<PartImages> rendered;
  for (int part = 0; part < 3; ++part) {
    RenderSettings settings = lone_settings;
    settings.share = {.part = part, .parts = 3};
    rendered.push_back(render_images(tracer, settings));
  }
  const std::vector<Image> whole = assemble(rendered, 7);
  for (size_t i = 0; i < whole.size(); ++i)
    expect_identical(whole[i], lone.images[i], image_names()[i]);
}

TEST(RenderShare, APartLeavesOtherPartsTilesEmpty) {
  PathTracer tracer;
  const PartImages part =
      render_images(tracer, {.samples_per_pixel = 1, .share = {.part = 1, .parts = 2}});
  const TileDeal deal{.width = kWidth, .height = kHeight, .tile_size = 16, .parts = 2};
  const Image& sums = part.images[0];
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      // The box filter's weights are positive: every owned pixel has weight, no other has any.
      ASSERT_EQ(sums.at(x, y, 3) != 0.f, deal.owner(x, y) == 1) << x << "," << y;
}

TEST(RenderShare, EveryPartSettlesOncePerPass) {
  PathTracer tracer;
  for (int spp : {1, 3, 16}) {
    SCOPED_TRACE(std::to_string(spp) + " spp");
    for (int part = 0; part < 3; ++part) {
      int settles = 0;
      RenderSettings settings{.samples_per_pixel = spp};
      settings.share = {.part = part, .parts = 3, .settle = [&](StopVerdict own) {
                          ++settles;
                          EXPECT_EQ(own, StopVerdict::kGoOn);
                          return own;
                        }};
      const RenderStats stats = render_images(tracer, settings).stats;
      EXPECT_EQ(settles, pass_count(spp)) << "part " << part;
      EXPECT_EQ(stats.samples_per_pixel, spp);
      EXPECT_FALSE(stats.partial);
    }
  }
}

TEST(RenderShare, ATeamTimeLimitVerdictStopsEveryPartAfterTheSamePass) {
  // The team says "time limit" at the first settle although no part's own clock says so: all
  // parts stop after the first pass, one sample per pixel, and together they are the lone
  // one-sample render.
  for (const IntegratorCase& c : integrators()) {
    SCOPED_TRACE(c.name);
    const PartImages one_sample = render_images(*c.integrator, {.samples_per_pixel = 1, .seed = 5});
    std::vector<PartImages> rendered;
    for (int part = 0; part < 3; ++part) {
      int settles = 0;
      RenderSettings settings{.samples_per_pixel = 64, .seed = 5};
      settings.share = {.part = part, .parts = 3, .settle = [&](StopVerdict own) {
                          ++settles;
                          return std::max(own, StopVerdict::kTimeLimit);
                        }};
      rendered.push_back(render_images(*c.integrator, settings));
      const RenderStats& stats = rendered.back().stats;
      EXPECT_EQ(settles, 1) << "part " << part;
      EXPECT_TRUE(stats.partial) << "part " << part;
      EXPECT_FALSE(stats.cancelled) << "part " << part;
      EXPECT_EQ(stats.samples_per_pixel, 1) << "part " << part;
    }
    const std::vector<Image> whole = assemble(rendered, 16);
    for (size_t i = 0; i < whole.size(); ++i)
      expect_identical(whole[i], one_sample.images[i], image_names()[i]);
  }
}

TEST(RenderShare, ATeamCancelVerdictStopsBeforeCountingThePass) {
  PathTracer tracer;
  int settles = 0;
  RenderSettings settings{.samples_per_pixel = 16};
  settings.share = {.part = 0, .parts = 2, .settle = [&](StopVerdict) {
                      return ++settles == 2 ? StopVerdict::kCancelled : StopVerdict::kGoOn;
                    }};
  const RenderStats stats = render_images(tracer, settings).stats;
  EXPECT_EQ(settles, 2);
  EXPECT_TRUE(stats.cancelled);
  EXPECT_TRUE(stats.partial);
  EXPECT_EQ(stats.samples_per_pixel, 1);  // the pass the team cancelled is not counted
}

TEST(RenderShare, ASharePartThatDoesNotExistIsRefused) {
  PathTracer tracer;
  for (WorkShare share : {WorkShare{.part = 3, .parts = 3}, WorkShare{.part = -1, .parts = 3},
                          WorkShare{.part = 0, .parts = 0}, WorkShare{.part = 5, .parts = 2}}) {
    SCOPED_TRACE(std::to_string(share.part) + " of " + std::to_string(share.parts));
    EXPECT_THROW(render_images(tracer, {.samples_per_pixel = 1, .share = share}), Error);
  }
}

}  // namespace
}  // namespace obscura
