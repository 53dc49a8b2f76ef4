#include "obscura/film/tiles.h"

#include <algorithm>
#include <mutex>

#include <tbb/parallel_for.h>

namespace obscura {

std::vector<Bounds2i> make_tiles(Bounds2i region, int tile_size) {
  std::vector<Bounds2i> tiles;
  for (int y = region.min.y; y < region.max.y; y += tile_size)
    for (int x = region.min.x; x < region.max.x; x += tile_size)
      tiles.push_back(
          {{x, y}, {std::min(x + tile_size, region.max.x), std::min(y + tile_size, region.max.y)}});
  return tiles;
}

void for_each_tile_parallel(Bounds2i region, int tile_size,
                            const std::function<void(const Bounds2i&)>& render_tile,
                            const ProgressCallback& progress) {
  for_each_tile_parallel(make_tiles(region, tile_size), render_tile, progress);
}

void for_each_tile_parallel(const std::vector<Bounds2i>& tiles,
                            const std::function<void(const Bounds2i&)>& render_tile,
                            const ProgressCallback& progress) {
  const int total = int(tiles.size());
  std::mutex progress_mutex;
  int done = 0;
  tbb::parallel_for(0, total, [&](int i) {
    render_tile(tiles[i]);
    if (progress) {
      std::lock_guard lock(progress_mutex);
      progress(++done, total);
    }
  });
}

}  // namespace obscura
