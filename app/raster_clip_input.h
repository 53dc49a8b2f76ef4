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
#include "obscura/raster/pipeline.h"

namespace obscura::app {

struct ClipTriangles {
  std::string name;
  int width = 0, height = 0;
  Rgb clear_color;  // 0–255 per channel, as the triangles' colours
  float clear_depth = 1.f;
  raster::DepthFunc depth_func = raster::DepthFunc::kLess;
  raster::CullMode cull = raster::CullMode::kNone;
  std::vector<uint32_t> ids;
  std::vector<Rgb> colors;     // 0–255
  std::vector<Vector4f> clip;  // three per triangle
};

// Reads and checks the file (a regular file of at most 64 MiB, as scene files).
ClipTriangles read_raster_clip_file(const std::string& file);
// Checks a parsed document; `file` names it in messages.
ClipTriangles parse_raster_clip(const nlohmann::ordered_json& document, const std::string& file);

}  // namespace obscura::app
