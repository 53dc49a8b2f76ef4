// The input of `obscura raster-clip`: triangles given directly in clip space, as the conformance
// format defines it (docs/rasterizer.md). Read strictly; every message names the file and the
// JSON path ("file.json: triangles[2].clip").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"
#include "obscura/raster/clip_triangles.h"

namespace obscura::app {

using raster::ClipTriangles;

// Reads and checks the file (a regular file of at most 64 MiB, as scene files).
ClipTriangles read_raster_clip_file(const std::string& file);
// Checks a parsed document; `file` names it in messages.
ClipTriangles parse_raster_clip(const nlohmann::ordered_json& document, const std::string& file);

}  // namespace obscura::app
