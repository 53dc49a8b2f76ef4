// The rasterizer's preparation kept across the frames of a session (raster/rasterizer_cache.h):
// frames drawn from a kept preparation are the frames a fresh preparation draws, bit for bit —
// for other cameras, with AOVs or without, with MSAA and with accumulated depth of field — and
// a scene is prepared once per setting, its textures and environment once for all settings. The
// reference is always raster::render preparing the scene for that frame alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/io/scene_loader.h"
#include "obscura/raster/rasterizer_cache.h"
#include "obscura/raster/render.h"
#include "test_paths.h"

namespace obscura::raster {
namespace {

struct Frame {
  Image film;
  std::vector<Image> aovs;
};

Frame draw(const Scene& scene, const Camera& camera, const RenderSettings& settings, bool aovs,
           RasterizerCache* cache) {
  const Bounds2i crop = camera.film.crop_pixels();
  Film film(crop.width(), crop.height());
  AovBuffers buffers(crop.width(), crop.height(), false);
  render(scene, camera, settings, film, aovs ? &buffers : nullptr, {}, cache);
  Frame frame{film.sums(), {}};
  if (aovs) frame.aovs = {buffers.depth(), buffers.normal(), buffers.id()};
  return frame;
}

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::equal(a.data.begin(), a.data.end(), b.data.begin(), [](float x, float y) {
           return std::bit_cast<uint32_t>(x) == std::bit_cast<uint32_t>(y);
         });
}

bool same_frame(const Frame& a, const Frame& b) {
  if (!same_bits(a.film, b.film) || a.aovs.size() != b.aovs.size()) return false;
  for (size_t i = 0; i < a.aovs.size(); ++i)
    if (!same_bits(a.aovs[i], b.aovs[i])) return false;
  return true;
}

// Spheres of many materials in an HDR environment (image-based lighting and background), 64 × 64.
Scene spheres() {
  Scene scene = load_scene_file(test::source_path("scenes/gltf-spheres.json"));
  scene.camera.film.width_px = scene.camera.film.height_px = 64;
  return scene;
}

Camera moved(const Camera& camera, double dx) {
  Camera c = camera;
  Transform shift = Transform::translate({dx, 0.1 * dx, 0});
  c.world_from_camera = AnimatedTransform(shift * camera.world_from_camera.at(0));
  return c;
}

TEST(RasterizerCache, FramesFromAKeptPreparationAreTheFreshFramesBitForBit) {
  const Scene scene = spheres();
  RasterizerCache cache(scene);
  RenderSettings settings;
  for (bool aovs : {true, false}) {
    const Frame still = draw(scene, scene.camera, settings, aovs, nullptr);
    const Frame moving = draw(scene, moved(scene.camera, 0.4), settings, aovs, nullptr);
    // The moved camera between two frames of the first: each from the kept preparation.
    for (const Frame* expected : {&still, &moving, &still})
      EXPECT_TRUE(
          same_frame(draw(scene, expected == &still ? scene.camera : moved(scene.camera, 0.4),
                          settings, aovs, &cache),
                     *expected))
          << (expected == &still ? "still" : "moved") << (aovs ? " with AOVs" : "");
  }
  // One preparation with AOV targets, one without: each kept for every later camera.
  EXPECT_EQ(cache.preparations(), 2);

  settings.msaa_samples = 4;
  EXPECT_TRUE(same_frame(draw(scene, scene.camera, settings, true, &cache),
                         draw(scene, scene.camera, settings, true, nullptr)));
  EXPECT_EQ(cache.preparations(), 3);
}

TEST(RasterizerCache, AccumulatedDepthOfFieldFromAKeptPreparationIsTheFreshFrame) {
  const Scene scene = spheres();
  Camera camera = scene.camera;
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 1.4;
  camera.lens.focus_distance_m = 5;
  RenderSettings settings;
  settings.depth_of_field = DepthOfFieldMethod::kAccumulate;
  settings.effect_samples = 4;
  RasterizerCache cache(scene);
  const Frame fresh = draw(scene, camera, settings, true, nullptr);
  for (int frame = 0; frame < 2; ++frame)
    EXPECT_TRUE(same_frame(draw(scene, camera, settings, true, &cache), fresh))
        << "frame " << frame;
  EXPECT_EQ(cache.preparations(), 1);
}

TEST(RasterizerCache, SettingsShareTheTexturesAndTheEnvironment) {
  const Scene scene = spheres();
  RasterizerCache cache(scene);
  RasterSettings one, other;
  other.msaa_samples = 8;
  other.shadow_map_size = 0;
  const auto first = cache.get(one);
  const auto second = cache.get(other);
  EXPECT_NE(first, second);
  EXPECT_EQ(first->surfaces(), second->surfaces());
  EXPECT_NE(first->surfaces()->environment_lighting, nullptr);
  EXPECT_EQ(cache.get(one), first);
}

TEST(RasterizerCache, KeepsTheMostRecentlyUsedSettings) {
  const Scene scene = spheres();
  RasterizerCache cache(scene);
  std::vector<RasterSettings> settings(RasterizerCache::kKept + 1);
  for (size_t i = 0; i < settings.size(); ++i) settings[i].shadow_map_size = 64 << i;
  for (const RasterSettings& s : settings) cache.get(s);
  EXPECT_EQ(cache.preparations(), int(settings.size()));
  cache.get(settings.back());  // kept
  EXPECT_EQ(cache.preparations(), int(settings.size()));
  cache.get(settings.front());  // the least recently used, let go
  EXPECT_EQ(cache.preparations(), int(settings.size()) + 1);
}

}  // namespace
}  // namespace obscura::raster
