// `obscura raster-clip FILE.json --out DIR`: the rasterizer's conformance door. Renders triangles
// given directly in clip space and writes NAME.png, NAME.ids.pgm, NAME.count.pgm and
// NAME.depth.pfm, so the pipeline can be compared pixel by pixel with other implementations.
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

void add_raster_clip_command(CLI::App& app);

}  // namespace obscura::app
