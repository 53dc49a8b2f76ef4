// Per-pixel shading of materials with glTF alpha: the tile pipeline compiled for
// WithCoverage<ScenePixelProgram>.
#include "obscura/raster/pipeline.h"
#include "obscura/raster/scene_draws.h"
#include "obscura/raster/scene_program.h"

namespace obscura::raster {

void draw_pixel_shaded_with_coverage(RenderTarget& target, const DrawState& state,
                                     const InstanceUniforms& u,
                                     std::span<const MeshVertex> vertices,
                                     std::span<const uint32_t> indices) {
  draw_with_depth_func<DepthFunc::kLess>(target, state, WithCoverage<ScenePixelProgram>{{u}},
                                         vertices, indices);
}

}  // namespace obscura::raster
