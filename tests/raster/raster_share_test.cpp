// The rasterizer drawing a frame in parts (RenderTarget::set_share, AccumulationSettings::share),
// as MPI ranks and --shard parts do: each part rasterizes only its 64-pixel tiles, and the parts'
// pixels put together must be the lone render's bit for bit — colour and the AOV images — for a
// single frame and for frames accumulated through a lens with depth of field. The reference is
// always the same scene drawn by one process.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "obscura/film/film.h"
#include "obscura/film/work_share.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/raster/accumulation.h"
#include "obscura/raster/binner.h"
#include "obscura/raster/scene_rasterizer.h"
#include "test_paths.h"

namespace obscura::raster {
namespace {

// 3 × 2 raster tiles, the last column and row cut short.
constexpr int kWidth = 160, kHeight = 120;

Scene example_scene(const std::string& name) {
  Scene scene = name == "cornell-box" ? load_scene(name)
                                      : load_scene_file(test::source_path("scenes/" + name));
  scene.camera.film.width_px = kWidth;
  scene.camera.film.height_px = kHeight;
  return scene;
}

// A part's (or the lone render's) images: the film's sums, then what its render target holds.
struct NamedImages {
  std::vector<std::string> names;
  std::vector<Image> images;
  void add(const std::string& name, Image image) {
    names.push_back(name);
    images.push_back(std::move(image));
  }
};

NamedImages target_images(const Film& film, const RenderTarget& target, const Camera& camera) {
  NamedImages out;
  out.add("film sums", film.sums());
  out.add("resolved colour", target.resolve_color());
  out.add("window depth", target.depth_image());
  if (target.has_aovs()) {
    out.add("view depth", target.view_depth_image());
    out.add("normal", normal_image(target));
    out.add("depth", depth_image(target));
    out.add("range", range_image(target, camera));
    out.add("id", id_image(target));
  }
  return out;
}

NamedImages assemble(const std::vector<NamedImages>& parts) {
  const TileDeal deal{
      .width = kWidth, .height = kHeight, .tile_size = kTileSize, .parts = int(parts.size())};
  NamedImages whole;
  for (size_t i = 0; i < parts.front().images.size(); ++i) {
    const Image& first = parts.front().images[i];
    Image image(first.width, first.height, first.channels);
    for (size_t p = 0; p < parts.size(); ++p)
      unpack_owned_pixels(deal, int(p), pack_owned_pixels(deal, int(p), parts[p].images[i]), image);
    whole.add(parts.front().names[i], std::move(image));
  }
  return whole;
}

void expect_identical(const NamedImages& actual, const NamedImages& expected) {
  ASSERT_EQ(actual.names, expected.names);
  for (size_t i = 0; i < expected.images.size(); ++i) {
    const Image &a = actual.images[i], &e = expected.images[i];
    const std::string& what = expected.names[i];
    ASSERT_EQ(a.width, e.width) << what;
    ASSERT_EQ(a.height, e.height) << what;
    ASSERT_EQ(a.channels, e.channels) << what;
    for (size_t v = 0; v < e.data.size(); ++v)
      if (std::memcmp(&a.data[v], &e.data[v], sizeof(float)) != 0) {
        const size_t pixel = v / size_t(e.channels);
        ADD_FAILURE() << what << ": first difference at pixel (" << pixel % size_t(e.width) << ", "
                      << pixel / size_t(e.width) << "): " << a.data[v] << " vs " << e.data[v];
        break;
      }
  }
}

// One sharp frame at mid-shutter, as `obscura render --renderer raster` draws it.
NamedImages draw_frame(const Scene& scene, const RasterSettings& settings, WorkShare share) {
  SceneRasterizer rasterizer(scene, settings);
  RenderTarget target = rasterizer.make_target(scene.camera);
  target.set_share(share.part, share.parts);
  Film film(kWidth, kHeight);
  rasterizer.render(scene.camera, film, &target);
  return target_images(film, target, scene.camera);
}

TEST(RasterShare, OneFrameInPartsIsTheLoneFrameBitForBit) {
  // The Cornell box, and a scene with spot and directional lights (shadow maps, drawn whole by
  // every part) and a glass sphere (blended last).
  for (const std::string name : {"cornell-box", "spheres-and-lights.json"}) {
    const Scene scene = example_scene(name);
    for (int msaa : {1, 4}) {
      SCOPED_TRACE(name + ", msaa " + std::to_string(msaa));
      RasterSettings settings;
      settings.msaa_samples = msaa;
      settings.aovs = true;
      const NamedImages lone = draw_frame(scene, settings, {});
      for (int parts : {2, 3, 5}) {
        SCOPED_TRACE(std::to_string(parts) + " parts");
        std::vector<NamedImages> rendered;
        for (int part = 0; part < parts; ++part)
          rendered.push_back(draw_frame(scene, settings, {.part = part, .parts = parts}));
        expect_identical(assemble(rendered), lone);
      }
    }
  }
}

TEST(RasterShare, WithoutAovsTheColourStillAssembles) {
  const Scene scene = example_scene("cornell-box");
  const NamedImages lone = draw_frame(scene, {}, {});
  std::vector<NamedImages> rendered;
  for (int part = 0; part < 2; ++part)
    rendered.push_back(draw_frame(scene, {}, {.part = part, .parts = 2}));
  expect_identical(assemble(rendered), lone);
}

TEST(RasterShare, APartDrawsOnlyItsTiles) {
  // Nothing is drawn into the other parts' tiles: their depth stays as cleared, while every
  // tile of the part's own has geometry in it (the Cornell box fills the frame).
  const Scene scene = example_scene("cornell-box");
  SceneRasterizer rasterizer(scene);
  RenderTarget target = rasterizer.make_target(scene.camera);
  target.set_share(1, 2);
  Film film(kWidth, kHeight);
  rasterizer.render(scene.camera, film, &target);
  const TileDeal deal{.width = kWidth, .height = kHeight, .tile_size = kTileSize, .parts = 2};
  const Image depth = target.depth_image();
  std::vector<int> drawn_pixels_per_tile(6, 0);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool drawn = depth.at(x, y, 0) < 1.f;
      if (deal.owner(x, y) != 1) {
        ASSERT_FALSE(drawn) << x << "," << y;
      }
      drawn_pixels_per_tile[size_t(deal.tile_at(x, y))] += drawn;
    }
  for (int tile = 1; tile < 6; tile += 2) EXPECT_GT(drawn_pixels_per_tile[size_t(tile)], 0) << tile;
}

struct Accumulated {
  NamedImages images;
  AccumulationStats stats;
};

// Frames through the lens (depth of field) accumulated as `--raster-dof accumulate` does, with
// the frame nearest mid-shutter kept for the AOVs.
Accumulated accumulate_frames(const Scene& scene, AccumulationSettings settings) {
  RasterSettings raster_settings;
  raster_settings.aovs = settings.aovs;
  SceneRasterizer rasterizer(scene, raster_settings);
  Film film(kWidth, kHeight);
  RenderTarget middle = rasterizer.make_target(scene.camera);
  Accumulated out;
  out.stats = accumulate(
      scene.camera, settings,
      [&](const FrameParameters& frame, RenderTarget& target) {
        rasterizer.render_frame(
            scene.camera, {frame.sample.time_s, frame.lens.view, frame.lens.projection}, target);
      },
      film, {}, &middle);
  out.images = target_images(film, middle, scene.camera);
  return out;
}

TEST(RasterShare, AccumulatedDepthOfFieldInPartsIsTheLoneRenderBitForBit) {
  const Scene scene = example_scene("depth-of-field.json");
  ASSERT_TRUE(scene.camera.lens.depth_of_field);
  const AccumulationSettings lone_settings{.samples = 6, .seed = 3, .aovs = true};
  const Accumulated lone = accumulate_frames(scene, lone_settings);
  EXPECT_EQ(lone.stats.frames, 6);
  for (int parts : {2, 3, 5}) {
    SCOPED_TRACE(std::to_string(parts) + " parts");
    std::vector<NamedImages> rendered;
    for (int part = 0; part < parts; ++part) {
      int settles = 0;
      AccumulationSettings settings = lone_settings;
      settings.share = {.part = part, .parts = parts, .settle = [&](StopVerdict own) {
                          ++settles;
                          return own;
                        }};
      Accumulated accumulated = accumulate_frames(scene, settings);
      // After every frame: each frame is a pass (film/pass_schedule.h).
      EXPECT_EQ(settles, lone_settings.samples) << "part " << part;
      EXPECT_EQ(accumulated.stats.frames, lone_settings.samples) << "part " << part;
      rendered.push_back(std::move(accumulated.images));
    }
    expect_identical(assemble(rendered), lone.images);
  }
}

TEST(RasterShare, ATeamVerdictStopsEveryPartBeforeTheSameFrame) {
  const Scene scene = example_scene("depth-of-field.json");
  // The team says "time limit" before the third frame: every part draws two frames, and so does
  // a lone render told the same.
  auto stop_before_third = [](int& settles) {
    return [&settles](StopVerdict own) {
      return ++settles == 2 ? std::max(own, StopVerdict::kTimeLimit) : own;
    };
  };
  int lone_settles = 0;
  const Accumulated lone = accumulate_frames(
      scene, {.samples = 8, .seed = 1, .share = {.settle = stop_before_third(lone_settles)}});
  ASSERT_EQ(lone.stats.frames, 2);
  ASSERT_TRUE(lone.stats.time_limited);
  std::vector<NamedImages> rendered;
  for (int part = 0; part < 3; ++part) {
    int settles = 0;
    Accumulated accumulated = accumulate_frames(
        scene, {.samples = 8,
                .seed = 1,
                .share = {.part = part, .parts = 3, .settle = stop_before_third(settles)}});
    EXPECT_EQ(accumulated.stats.frames, 2) << "part " << part;
    EXPECT_TRUE(accumulated.stats.time_limited) << "part " << part;
    EXPECT_FALSE(accumulated.stats.cancelled) << "part " << part;
    rendered.push_back(std::move(accumulated.images));
  }
  expect_identical(assemble(rendered), lone.images);
}

TEST(RasterShare, ASharePartThatDoesNotExistIsRefused) {
  RenderTarget target(8, 8);
  EXPECT_THROW(target.set_share(2, 2), Error);
  EXPECT_THROW(target.set_share(-1, 2), Error);
  EXPECT_THROW(target.set_share(0, 0), Error);
  const Scene scene = example_scene("depth-of-field.json");
  EXPECT_THROW(accumulate_frames(scene, {.samples = 2, .share = {.part = 4, .parts = 4}}), Error);
}

}  // namespace
}  // namespace obscura::raster
