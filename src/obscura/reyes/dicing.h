// Split and dice: how REYES turns a triangle into grids of micropolygons.
//
// A triangle is diced as a degenerate quad (its shortest projected edge as the base, the
// opposite vertex as both top corners) on a lattice of nu × nv micropolygons, nu and nv chosen from
// the projected edge lengths so that no micropolygon is wider than √(shading rate) pixels anywhere
// (perspective makes the step along an edge vary by the ratio of its end depths, which the rates
// include).
//
// No cracks: the vertices on a triangle's edge are placed by that edge alone. Each edge has its
// own rate, computed from its two endpoints and nothing else, and its lattice vertices are
// snapped onto that rate's points, evaluated from the endpoints in one canonical order; two
// triangles sharing an edge therefore put bit-identical vertices on it, and the sampler's
// edge rule gives every sample on it to exactly one side.
//
// Split: a lattice larger than the grid size is cut into blocks of at most that many
// micropolygons; blocks share their boundary vertices (the lattice is one function of (i, j)),
// so splitting adds no cracks either. A piece whose lattice would be huge, or that perspective
// stretches (a ground plane running into the distance), is first split into four at its edge
// midpoints so that each part dices at its own rate; where such a split meets an unsplit
// neighbour its edges are straight segments of the neighbour's edge, a T-junction whose vertex
// lies on the neighbour's edge to rounding (double precision: no sample falls in between). A
// triangle crossing the near plane is first split into four at its edge midpoints (an eye split), a
// bounded number of times; what still crosses the plane then is dropped with one warning per frame.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "obscura/math/vector.h"
#include "obscura/reyes/frame_view.h"

namespace obscura::reyes {

// Where a lattice vertex is: camera space at the exposure's open and close, and its barycentric
// coordinates (b1, b2) in the scene triangle it lies on (b0 = 1 − b1 − b2).
struct LatticePoint {
  Point3d open, close;
  Point2d bary;
};

// A piece of a scene triangle (the whole triangle, or a part an eye split made): its corners.
struct Piece {
  uint32_t instance = 0, triangle = 0;
  std::array<LatticePoint, 3> corners;
};

// A piece's lattice: corners reordered so that (c0, c1) is the base and c2 the apex.
struct DicePlan {
  Piece piece;
  // Rates of the base (c0 c1), left (c0 c2) and right (c1 c2) edges, and whether each edge's
  // canonical order runs against the piece's.
  std::array<int, 3> edge_rate = {1, 1, 1};
  std::array<bool, 3> flipped = {false, false, false};
  int nu = 1, nv = 1;
  double depth_ratio = 1;  // farthest over nearest corner (perspective)

  // Whether the piece should rather be split before dicing: perspective stretches it over more
  // than kMaxDepthRatio (its rates would be set by its near end everywhere), or its lattice
  // holds more than kMaxLattice micropolygons.
  bool too_large() const;
};

inline constexpr double kMaxDepthRatio = 2;
inline constexpr long long kMaxLattice = 1 << 16;
// How often a piece is split for size at most (each split quarters it).
inline constexpr int kMaxSizeSplits = 10;

// A rectangle [i0, i1] × [j0, j1] of a plan's lattice (micropolygons i0..i1−1, j0..j1−1): one
// grid, with where it can land on the film over the shutter and lens.
struct Block {
  uint32_t plan = 0;
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  RasterBounds bounds;
  double depth_min = 0;  // the nearest it comes (occlusion culling)
  bool sphere = false;   // a block of a sphere patch (sphere_patches.h): `plan` is a PatchPlan
};

// The most micropolygons along one lattice side (a bound on the time a huge, near triangle
// takes; the shading rate is then not met, which the stats show).
inline constexpr int kMaxLatticeRate = 4096;

struct DiceLimits {
  double side_px = 1;   // √(shading rate)
  int grid_size = 256;  // micropolygons per block at most
};

// Where a piece in front of the near plane can land on the film: its corners at both exposure
// ends, grown by the largest lens shift at their depths.
RasterBounds piece_bounds(const FrameView& view, const Piece& piece);
// The plan of a piece in front of the near plane (every corner depth ≥ near at both times).
DicePlan plan_dicing(const FrameView& view, const Piece& piece, const DiceLimits& limits);
// The lattice vertex (i, j) of a plan (0 ≤ i ≤ nu, 0 ≤ j ≤ nv).
LatticePoint lattice_point(const DicePlan& plan, int i, int j);
// The cells per block, along u and along v, that cut a lattice of nu × nv cells into square-ish
// blocks of at most `grid_size` micropolygons (a thin lattice takes long thin ones).
std::array<int, 2> block_cells(int grid_size, int nu, int nv);
// Cuts a plan's lattice into blocks (appended, in row order), each with its bounds: over both
// exposure ends and, with depth of field, grown by the largest lens shift at its depths.
void cut_blocks(const FrameView& view, const DicePlan& plan, uint32_t plan_index,
                const DiceLimits& limits, std::vector<Block>& blocks);

// What happened to a piece against the near plane.
enum class EyeVerdict { kInFront, kBehind, kOutside, kStraddles };
// Perspective only: kBehind when every corner is nearer than the near plane at both times,
// kOutside when the piece lies beyond one side of the view frustum (grown by `margin_px`),
// kStraddles when it crosses the near plane, else kInFront. Orthographic: always kInFront.
EyeVerdict eye_verdict(const FrameView& view, const Piece& piece, double margin_px);
// The same for any surface inside the convex hull of camera-space `points` (each at both times).
EyeVerdict eye_verdict(const FrameView& view, const std::vector<Point3d>& points, double margin_px);
// The four pieces of an eye split (edge midpoints).
std::array<Piece, 4> split_in_four(const Piece& piece);

}  // namespace obscura::reyes
