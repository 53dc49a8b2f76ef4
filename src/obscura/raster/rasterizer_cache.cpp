#include "obscura/raster/rasterizer_cache.h"

#include <algorithm>

namespace obscura::raster {

std::shared_ptr<const SceneRasterizer> RasterizerCache::get(const RasterSettings& settings) {
  std::lock_guard lock(mutex_);
  auto found = std::find_if(kept_.begin(), kept_.end(),
                            [&](const auto& entry) { return entry.first == settings; });
  if (found != kept_.end()) {
    std::rotate(found, found + 1, kept_.end());
    return kept_.back().second;
  }
  // Prepared under the lock: two frames asking for the same settings at once prepare once. The
  // surfaces (textures, materials, environment) are the same for every setting: shared.
  auto prepared = std::make_shared<SceneRasterizer>(
      scene_, settings, kept_.empty() ? nullptr : kept_.back().second->surfaces());
  ++preparations_;
  if (kept_.size() >= kKept) kept_.erase(kept_.begin());
  kept_.emplace_back(settings, prepared);
  return prepared;
}

void RasterizerCache::meshes_changed(std::span<const uint32_t> meshes) {
  std::lock_guard lock(mutex_);
  for (auto& entry : kept_) entry.second->update_meshes(scene_, meshes);
}

}  // namespace obscura::raster
