// Gouraud shading: the tile pipeline compiled for SceneGouraudProgram, with and without coverage.
#include "obscura/raster/pipeline.h"
#include "obscura/raster/scene_draws.h"
#include "obscura/raster/scene_program.h"

namespace obscura::raster {

void draw_gouraud_shaded(RenderTarget& target, const DrawState& state, const InstanceUniforms& u,
                         bool with_coverage, std::span<const MeshVertex> vertices,
                         std::span<const uint32_t> indices) {
  if (with_coverage)
    return draw_with_depth_func<DepthFunc::kLess>(
        target, state, WithCoverage<SceneGouraudProgram>{{u}}, vertices, indices);
  draw_with_depth_func<DepthFunc::kLess>(target, state, SceneGouraudProgram{u}, vertices, indices);
}

}  // namespace obscura::raster
