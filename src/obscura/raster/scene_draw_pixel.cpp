// Per-pixel shading of opaque materials: the tile pipeline compiled for ScenePixelProgram.
#include "obscura/raster/pipeline.h"
#include "obscura/raster/scene_draws.h"
#include "obscura/raster/scene_program.h"

namespace obscura::raster {

void draw_pixel_shaded(RenderTarget& target, const DrawState& state, const InstanceUniforms& u,
                       std::span<const MeshVertex> vertices, std::span<const uint32_t> indices) {
  draw_with_depth_func<DepthFunc::kLess>(target, state, ScenePixelProgram{u}, vertices, indices);
}

}  // namespace obscura::raster
