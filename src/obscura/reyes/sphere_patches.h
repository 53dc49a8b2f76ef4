// Analytic spheres diced natively: a sphere kept as centre and radius (Mesh::analytic_sphere)
// is cut into patches of its (u, v) parameters — u = φ/2π around +Y from +Z towards +X, v = θ/π
// from the +Y pole, the tessellation's texture coordinates — and each patch is diced on a
// lattice of points that lie on the sphere itself.
//
// No cracks. The patches of one sphere are one uniform rows × 2·rows array: the number of rows
// is chosen for the whole sphere (doubled while any patch's lattice would hold more than
// kMaxLattice micropolygons), never per patch, so two patches sharing an edge share all of it,
// with the same parameters at its ends. An edge's rate is computed from that edge alone (its
// projected length at the shading time, measured along the curve), the lattice's vertices on
// the edge are snapped onto the rate's points, and every point is evaluated from its (u, v) by
// one function; the two patches therefore put bit-identical vertices on their shared edge, as
// neighbouring triangles do (dicing.h). The seam is one edge: u = 1 is evaluated as u = 0.
//
// Poles: the edge along a pole has length zero, rate 1, and every lattice vertex on it is the
// pole itself (evaluated exactly, whatever u), so the patches around a pole meet at one point
// and the micropolygons touching it are triangles of a fan, with no sliver left open.
//
// Displacement (the material's, Displacement) moves every point along the sphere's normal
// before anything else sees it — rates, bounds, the hider — by the displacement at its (u, v),
// read at the seam's and the poles' one canonical (u, v) so that shared points stay shared.
// A patch's culling bounds grow by the larger of the material's bound and the displacement's
// real largest value, so an under-stated bound leaves no hole; the vertices displaced beyond
// it are counted (`displacement_overruns`) and warned about.
//
// A patch that crosses the near plane is eye-split into four at its parameter midpoints, as a
// triangle is (what still crosses it after the limit is dropped, with one warning); like the
// triangles' eye splits, those pieces may meet their neighbours at T-junctions near the plane.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "obscura/math/transform.h"
#include "obscura/math/vector.h"
#include "obscura/reyes/dicing.h"
#include "obscura/reyes/frame_view.h"
#include "obscura/reyes/grid.h"
#include "obscura/reyes/reyes_scene.h"

namespace obscura::reyes {

// A sphere instance as the frame sees it: the sphere in object space and where object space is
// in camera space at the exposure's two ends.
struct SphereFrame {
  uint32_t instance = 0;
  Point3d center;
  double radius = 1;
  Transform camera_from_object_open, camera_from_object_close;
  // Its material's displacement (none when null): every point moves along the normal by it,
  // its bounds grow by `reach` (the larger of the displacement's bound and its largest value).
  const Displacement* displacement = nullptr;
  double reach = 0;
};

// A rectangle of a sphere's parameters, u in [0, 1] around, v in [0, 1] from the +Y pole.
struct PatchRect {
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
};

// A patch's lattice: nu × nv micropolygons; edge rates of the top (v = v0), bottom (v = v1),
// left (u = u0) and right (u = u1) edges.
struct PatchPlan {
  uint32_t sphere = 0;  // its SphereFrame
  PatchRect rect;
  std::array<int, 4> edge_rate = {1, 1, 1, 1};
  int nu = 1, nv = 1;
};

// The most patch rows a sphere is cut into (twice as many columns).
inline constexpr int kMaxPatchRows = 256;

// The unit direction from the centre at parameters (u, v): the poles and the seam exactly.
Point3d sphere_direction(double u, double v);
// The lattice vertex (i, j) of a plan (camera space at both exposure ends; `bary` holds (u, v)).
LatticePoint patch_point(const SphereFrame& sphere, const PatchPlan& plan, int i, int j);

// What splitting the spheres produced: plans, and their blocks (Block::sphere set, Block::plan
// indexing `plans`), in a fixed order.
struct PatchSplit {
  std::vector<PatchPlan> plans;
  std::vector<Block> blocks;
  uint64_t pieces = 0, eye_splits = 0, eye_split_culled = 0;
};

// Cuts sphere `sphere_index` (`sphere`) into patches, eye-splits those crossing the near plane,
// drops those that cannot reach `region`, plans the rest and cuts them into blocks.
void split_sphere(const FrameView& view, const SphereFrame& sphere, uint32_t sphere_index,
                  const DiceLimits& limits, int eye_split_limit, const RasterBounds& region,
                  double margin_px, PatchSplit& out);

// Dices `block` of a patch and shades its vertices at the shading time, with the sphere's exact
// normal and its (u, v) as texture coordinates.
Grid dice_and_shade_patch(const ReyesScene& scene, const FrameView& view, const SphereFrame& sphere,
                          const PatchPlan& plan, const Block& block, uint64_t key,
                          GridCounts& counts);

}  // namespace obscura::reyes
