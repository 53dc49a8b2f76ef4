// REYES's entry point: one frame of a compiled scene, bucket by bucket.
//
//   split   every triangle of every instance becomes a piece, every analytic sphere an array
//           of patches (sphere_patches.h); pieces crossing the near plane are eye-split
//           (dicing.h), pieces off the film dropped; each piece's lattice is planned from its
//           projected edges and cut into blocks of at most the grid size
//   bucket  the work share's tiles (a bucket is at most a tile) are cut into buckets; every
//           block is listed in the buckets its bounds reach
//   dice    a block becomes a grid, diced and shaded (grid.h) when the first bucket that needs
//           it is sampled, and freed when the last one is done: grids live only while a bucket
//           that needs them is unfinished
//   sample  each bucket's hider (hider.h) tests the micropolygons of its grids, nearest first
//           (a grid behind every sample's opaque hit is neither diced nor sampled: occlusion
//           culling), against its samples, then composites and filters them into the film
//
// Every pixel is rendered whole by one bucket from samples keyed on the pixel, and every grid
// is a pure function of its block, so the image is bit-identical for any number of threads,
// bucket size and work share.
#pragma once

#include <vector>

#include "obscura/film/tiles.h"
#include "obscura/reyes/hider.h"
#include "obscura/reyes/reyes_scene.h"
#include "obscura/reyes/reyes_settings.h"

namespace obscura {
class AovBuffers;
class Film;
struct Camera;
}  // namespace obscura

namespace obscura::reyes {

// Renders `camera` into `film` (the camera's crop size) and, if given, `aovs`. Throws
// obscura::Error for settings out of range (naming the option), a film of another size or a
// camera REYES does not draw.
// With `seen`, the scene triangle each pixel's first sample sees (resized to the film's pixels).
ReyesStats render(const ReyesScene& scene, const Camera& camera, const ReyesSettings& settings,
                  Film& film, AovBuffers* aovs, const ProgressCallback& progress = {},
                  std::vector<SeenTriangle>* seen = nullptr);

}  // namespace obscura::reyes
