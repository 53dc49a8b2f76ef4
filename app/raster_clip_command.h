// `obscura raster-clip FILE.json --out DIR`: the rasterizer's conformance door. Renders triangles
// given directly in clip space and writes NAME.png, NAME.ids.pgm, NAME.count.pgm and
// NAME.depth.pfm, so the pipeline can be compared pixel by pixel with other implementations.
#pragma once

#include <cstdint>
#include <vector>

#include <CLI/CLI.hpp>

#include "obscura/film/image.h"
#include "raster_clip_input.h"

namespace obscura::app {

void add_raster_clip_command(CLI::App& app);

// What raster-clip writes, in memory: the colour (linear), ids and coverage counts per pixel (row
// 0 first), and the depth buffer.
struct RasterClipImages {
  Image color;
  std::vector<uint32_t> ids, count;
  Image depth;
};
RasterClipImages rasterize(const ClipTriangles& input);

}  // namespace obscura::app
