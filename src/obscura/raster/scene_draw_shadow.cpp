// Shadow-map depth: the tile pipeline compiled for the depth-only programs.
#include "obscura/raster/pipeline.h"
#include "obscura/raster/scene_draws.h"
#include "obscura/raster/scene_program.h"
#include "obscura/raster/shadow_map.h"

namespace obscura::raster {

void draw_shadow_depth(RenderTarget& depth, const DrawState& state,
                       const Matrix4f& clip_from_object, const SurfaceMaterial* cutout,
                       std::span<const MeshVertex> vertices, std::span<const uint32_t> indices) {
  if (cutout)
    return draw_with_depth_func<DepthFunc::kLess>(
        depth, state, DepthCoverageProgram{clip_from_object, cutout}, vertices, indices);
  draw_with_depth_func<DepthFunc::kLess>(
      depth, state, DepthOnlyProgram<MeshVertex>{clip_from_object}, vertices, indices);
}

}  // namespace obscura::raster
