// Splitting a film region into tiles and rendering them in parallel with oneTBB.
#pragma once

#include <functional>
#include <vector>

#include "obscura/math/bounds.h"

namespace obscura {

// Called with the number of finished tiles and the total, never concurrently, in increasing order
// of `done`. Runs on a worker thread: keep it short.
using ProgressCallback = std::function<void(int done, int total)>;

// The tiles of `region`, row by row, each at most tile_size × tile_size pixels.
std::vector<Bounds2i> make_tiles(Bounds2i region, int tile_size);

// Runs `render_tile` on every tile of `region` in parallel; returns when all are done.
// `render_tile` must write only inside its tile.
void for_each_tile_parallel(Bounds2i region, int tile_size,
                            const std::function<void(const Bounds2i&)>& render_tile,
                            const ProgressCallback& progress = {});
// The same over a list of tiles (which must not overlap); progress counts them.
void for_each_tile_parallel(const std::vector<Bounds2i>& tiles,
                            const std::function<void(const Bounds2i&)>& render_tile,
                            const ProgressCallback& progress = {});

}  // namespace obscura
