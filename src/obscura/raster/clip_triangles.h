// Triangles given directly in clip space, drawn flat-coloured with the pipeline's clipper, fill
// rule and depth test and nothing else: the rasterizer's conformance door, so that its pixels can
// be compared one by one with another implementation's (Mesa llvmpipe, docs/rasterizer.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/film/image.h"
#include "obscura/math/vector.h"
#include "obscura/raster/draw_modes.h"

namespace obscura::raster {

struct ClipTriangles {
  std::string name;
  int width = 0, height = 0;
  Rgb clear_color;  // 0–255 per channel, as the triangles' colours
  float clear_depth = 1.f;
  DepthFunc depth_func = DepthFunc::kLess;
  CullMode cull = CullMode::kNone;
  std::vector<uint32_t> ids;
  std::vector<Rgb> colors;     // 0–255, sRGB-encoded as a PNG stores them
  std::vector<Vector4f> clip;  // three per triangle
};

// What drawing them gives: the colour (linear), per pixel the id of the triangle seen (0: none)
// and how many triangles cover it (depth test off), row 0 first, and the depth buffer.
struct ClipTriangleImages {
  Image color;
  std::vector<uint32_t> ids, count;
  Image depth;
};

// Precondition: width, height > 0; ids and colors hold one entry per triangle.
ClipTriangleImages draw_clip_triangles(const ClipTriangles& triangles);

}  // namespace obscura::raster
