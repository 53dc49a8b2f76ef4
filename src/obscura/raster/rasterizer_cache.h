// The rasterizers a scene was prepared into, kept across frames. Preparing a SceneRasterizer —
// meshes in the rasterizer's vertex format, mipmapped textures, the environment's image-based
// lighting — costs far more than drawing a small frame of a textured model (DamagedHelmet under
// the studio map at 640 × 360: about 1 s of preparation for a few tens of ms of drawing), so the
// frames of a render session (a sequence, a Python loop, the live view) share one per setting.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <utility>
#include <vector>

#include "obscura/raster/scene_rasterizer.h"

namespace obscura {
struct Scene;
}

namespace obscura::raster {

class RasterizerCache {
 public:
  // `scene` must outlive the cache and change only as meshes_changed() says.
  explicit RasterizerCache(const Scene& scene) : scene_(scene) {}

  // The scene prepared with `settings`: kept from an earlier frame, or prepared now (and the
  // least recently used of more than kKept settings let go). Thread-safe; a rasterizer stays
  // valid while its holder keeps it, whatever the cache drops.
  std::shared_ptr<const SceneRasterizer> get(const RasterSettings& settings);

  // The scene's meshes `meshes` were posed again: every kept rasterizer brings them up to date
  // (SceneRasterizer::update_meshes) before its next frame. Not while a frame is drawn.
  void meshes_changed(std::span<const uint32_t> meshes);

  int preparations() const { return preparations_; }  // rasterizers prepared (tests)

  static constexpr size_t kKept = 4;

 private:
  const Scene& scene_;
  std::mutex mutex_;
  // Most recently used last.
  std::vector<std::pair<RasterSettings, std::shared_ptr<SceneRasterizer>>> kept_;
  int preparations_ = 0;
};

}  // namespace obscura::raster
