// The renderers Obscura offers, by the names the command line and files use.
#pragma once

#include <optional>
#include <string_view>

namespace obscura {

enum class Renderer {
  kPath,     // path tracer (trace/path_tracer.h)
  kWhitted,  // Whitted-style recursive ray tracer (trace/whitted.h)
  kDirect,   // direct lighting only (trace/direct_lighting.h)
  kRaster,   // the software rasterizer (raster/render.h)
};

// "path", "whitted", "direct", "raster"; nothing for any other name.
std::optional<Renderer> parse_renderer(std::string_view name);
const char* renderer_name(Renderer renderer);

// Whether it traces rays (the tracer's integrators) rather than rasterizing.
bool is_tracer(Renderer renderer);
// Whether its AOVs include an albedo (the rasterizer keeps none).
bool renders_albedo(Renderer renderer);
// The side of the square tiles it renders, and so deals to the parts of a frame rendered
// together (film/work_share.h): the tracer's 16-pixel tiles, the rasterizer's 64-pixel bins.
int tile_size(Renderer renderer);

}  // namespace obscura
