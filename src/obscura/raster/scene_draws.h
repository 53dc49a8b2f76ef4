// The scene's draw calls, one per program (scene_program.h). Each instantiates the whole tile
// pipeline for its program — most of the rasterizer's compile time — so they live in separate
// translation units: a build runs them on every core, and a change to one shader rebuilds one.
#pragma once

#include <cstdint>
#include <span>

namespace obscura::raster {

class RenderTarget;
struct Matrix4f;
struct DrawState;
struct InstanceUniforms;
struct MeshVertex;
struct SurfaceMaterial;

// Per-pixel shading (ScenePixelProgram); `with_coverage` for a material with glTF alpha.
void draw_pixel_shaded(RenderTarget& target, const DrawState& state, const InstanceUniforms& u,
                       std::span<const MeshVertex> vertices, std::span<const uint32_t> indices);
void draw_pixel_shaded_with_coverage(RenderTarget& target, const DrawState& state,
                                     const InstanceUniforms& u,
                                     std::span<const MeshVertex> vertices,
                                     std::span<const uint32_t> indices);
// Lighting at the vertices (SceneGouraudProgram), with the material's coverage or without.
void draw_gouraud_shaded(RenderTarget& target, const DrawState& state, const InstanceUniforms& u,
                         bool with_coverage, std::span<const MeshVertex> vertices,
                         std::span<const uint32_t> indices);
// Depth alone into a shadow map; `cutout`, where given, is the material whose coverage cuts the
// shadow (state.alpha_test set).
void draw_shadow_depth(RenderTarget& depth, const DrawState& state,
                       const Matrix4f& clip_from_object, const SurfaceMaterial* cutout,
                       std::span<const MeshVertex> vertices, std::span<const uint32_t> indices);

}  // namespace obscura::raster
