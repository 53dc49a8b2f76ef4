#include "obscura/render/renderer.h"

#include "obscura/raster/render_target.h"
#include "obscura/trace/render.h"

namespace obscura {

std::optional<Renderer> parse_renderer(std::string_view name) {
  for (Renderer r : {Renderer::kPath, Renderer::kWhitted, Renderer::kDirect, Renderer::kRaster})
    if (name == renderer_name(r)) return r;
  return std::nullopt;
}

const char* renderer_name(Renderer renderer) {
  switch (renderer) {
    case Renderer::kPath:
      return "path";
    case Renderer::kWhitted:
      return "whitted";
    case Renderer::kDirect:
      return "direct";
    case Renderer::kRaster:
      return "raster";
  }
  return "unknown";
}

bool is_tracer(Renderer renderer) {
  return renderer != Renderer::kRaster;
}

bool renders_albedo(Renderer renderer) {
  return is_tracer(renderer);
}

int tile_size(Renderer renderer) {
  return is_tracer(renderer) ? RenderSettings().tile_size : raster::kTileSize;
}

}  // namespace obscura
