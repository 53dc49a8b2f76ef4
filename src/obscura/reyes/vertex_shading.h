// What every primitive REYES dices shares once its vertices are placed: a grid started with its
// material's coverage, each vertex shaded once from the surface the primitive describes there
// (grid_shading.cpp), and the grid projected and counted.
#pragma once

#include <cstdint>
#include <optional>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"
#include "obscura/reyes/dicing.h"
#include "obscura/reyes/frame_view.h"
#include "obscura/reyes/grid.h"
#include "obscura/scene/mesh.h"
#include "obscura/shading/surface_material.h"

namespace obscura::reyes {

class ReyesScene;

// The surface at one grid vertex at the shading time, world space.
struct VertexSurface {
  Point3d position;
  Vector3f true_normal;             // unit: the surface's own side (a triangle's winding)
  Vector3f shading_normal;          // unit: interpolated (or exact, for an analytic surface)
  std::optional<Vector4f> tangent;  // xyz along +u, w the bitangent's sign (normal maps)
  Point2f uv[Mesh::kUvSets] = {};
  Rgb color = Rgb(1.f);  // the vertex colour
  float alpha = 1;       // the vertex colour's α
};

// A grid of `block`'s size for `instance` (its id) and the primitive's `triangle`, with the
// coverage of material `m`; its vertices are added by the caller, then shaded.
Grid start_grid(const Block& block, uint64_t key, uint32_t instance, uint32_t triangle,
                const shading::SurfaceMaterial& m, bool moves);
// Shades one vertex as the rasterizer's per-pixel program shades a fragment, and appends its
// colour, its viewer-facing normal (the AOV) and, for a non-opaque material, its α to `g`.
void shade_vertex(const ReyesScene& scene, const FrameView& view, const shading::SurfaceMaterial& m,
                  const VertexSurface& s, Grid& g);
// Projects the grid once (a still, sharp frame keeps it) and adds its counts: micropolygons,
// shaded vertices, the micropolygons' areas as diced.
void finish_grid(const FrameView& view, Grid& g, GridCounts& counts);

}  // namespace obscura::reyes
