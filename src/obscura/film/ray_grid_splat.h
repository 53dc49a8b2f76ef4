// Irradiance from a grid of rays: rays started from a regular grid of points (on a lens's front,
// for flare ghosts) and followed to the film land on a warped grid there. Each cell keeps the
// light that entered it, so the irradiance over the cell's image is its power divided by the
// image's area: a smooth picture from a few thousand rays, without Monte Carlo noise (the idea of
// Hullin et al., "Physically-Based Real-Time Lens Flare Rendering", SIGGRAPH 2011).
//
// Each cell is split into two triangles; a triangle covering pixels adds its power / area to the
// pixels whose centres it covers (shared edges counted once: the top-left rule). One smaller
// than a pixel adds its power at its centroid, spread bilinearly over the four nearest pixel
// centres, so that light folded into caustics keeps its energy. A per-vertex "gauge" (≤ 1 where
// the ray passed every opening of the optics) is interpolated across the triangle, and the
// pixels where it exceeds 1 get nothing: the openings' edges (a polygonal iris) are cut sharply
// between rays rather than at the grid's resolution.
#pragma once

#include <array>
#include <vector>

#include "obscura/film/image.h"
#include "obscura/math/vector.h"

namespace obscura {

struct RayGrid {
  int cells = 0;  // per side: (cells + 1)² vertices, row-major
  // Where each ray landed, in the image's pixels ((0, 0) its top-left corner); a vertex whose
  // ray was lost is marked by a non-finite x, and the triangles using it are dropped.
  std::vector<Point2d> position_px;
  std::vector<double> gauge;  // per vertex; ≤ 1: the ray passed
  // Per vertex and channel: the power the rays carry per unit area of the starting grid (in the
  // image's units × pixel area); a triangle's power is its starting area × the mean of its three.
  std::vector<std::array<float, 3>> power_density;
  double cell_area = 1;  // area of one cell of the starting grid

  int vertices_per_side() const { return cells + 1; }
};

// Adds the grid's irradiance to channels 0–2 of `image`, only to rows [row_begin, row_end)
// (callers split the image into row bands, one per thread, each receiving every grid in the
// same order: the sums are then the same for any thread count).
void splat_ray_grid(const RayGrid& grid, Image& image, int row_begin, int row_end);

}  // namespace obscura
