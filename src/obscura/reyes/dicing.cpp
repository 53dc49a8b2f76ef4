#include "obscura/reyes/dicing.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace obscura::reyes {

namespace {

LatticePoint lerp(const LatticePoint& a, const LatticePoint& b, double t) {
  return {a.open + (b.open - a.open) * t, a.close + (b.close - a.close) * t,
          a.bary + (b.bary - a.bary) * t};
}

// The canonical order of an edge's endpoints: lexicographic in their positions, so that two
// triangles naming the edge from either end (or through duplicated vertices) agree.
bool before(const LatticePoint& a, const LatticePoint& b) {
  const double ka[6] = {a.open.x, a.open.y, a.open.z, a.close.x, a.close.y, a.close.z};
  const double kb[6] = {b.open.x, b.open.y, b.open.z, b.close.x, b.close.y, b.close.z};
  return std::lexicographical_compare(ka, ka + 6, kb, kb + 6);
}

double distance(Point2d a, Point2d b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y));
}

int rate_for(double length_px, double side_px) {
  const double n = std::ceil(length_px / side_px);
  if (!(n < kMaxLatticeRate)) return kMaxLatticeRate;  // NaN too
  return std::max(1, int(n));
}

// An edge's projected length at the shading time (so that the same surface dices alike with
// motion blur on or off) and the ratio of its end depths then, by which perspective
// stretches its nearest step over its mean one.
struct EdgeMeasure {
  double length_px = 0, depth_ratio = 1;
};

Point3d at_shading_time(const FrameView& view, const LatticePoint& p) {
  return p.open + (p.close - p.open) * view.motion_fraction(view.shading_time_s());
}

EdgeMeasure measure(const FrameView& view, const LatticePoint& a, const LatticePoint& b) {
  EdgeMeasure m;
  m.length_px =
      distance(view.project(at_shading_time(view, a)), view.project(at_shading_time(view, b)));
  if (view.perspective()) {
    const double da = FrameView::depth(at_shading_time(view, a)),
                 db = FrameView::depth(at_shading_time(view, b));
    m.depth_ratio = std::max(da, db) / std::min(da, db);
  }
  return m;
}

// The lattice vertex i of n along the edge a → b of rate e: snapped to the edge's own points,
// evaluated in canonical order, the endpoints returned exactly.
LatticePoint edge_point(const LatticePoint& a, const LatticePoint& b, int e, bool flipped, int i,
                        int n) {
  long long k = (2LL * i * e + n) / (2LL * n);
  const LatticePoint& from = flipped ? b : a;
  const LatticePoint& to = flipped ? a : b;
  if (flipped) k = e - k;
  if (k <= 0) return from;
  if (k >= e) return to;
  return lerp(from, to, double(k) / e);
}

}  // namespace

RasterBounds piece_bounds(const FrameView& view, const Piece& piece) {
  RasterBounds b;
  double d0 = 1e300, d1 = -1e300;
  for (const LatticePoint& c : piece.corners)
    for (const Point3d& p : {c.open, c.close}) {
      const Point2d r = view.project(p);
      b.add(r.x, r.y);
      d0 = std::min(d0, FrameView::depth(p)), d1 = std::max(d1, FrameView::depth(p));
    }
  if (view.defocused()) b.grow(view.max_lens_shift_px(d0, d1));
  return b;
}

DicePlan plan_dicing(const FrameView& view, const Piece& piece, const DiceLimits& limits) {
  const auto& c = piece.corners;
  static constexpr int kEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  EdgeMeasure m[3];
  int base = 0;
  for (int e = 0; e < 3; ++e) {
    m[e] = measure(view, c[kEdges[e][0]], c[kEdges[e][1]]);
    // The shortest edge as the base: the lattice is about base × longest side micropolygons,
    // so a sliver (a fan's wedge) dices into one thin row rather than a square of them.
    if (m[e].length_px < m[base].length_px) base = e;
  }
  DicePlan plan;
  plan.piece = piece;
  const int p = kEdges[base][0], q = kEdges[base][1], r = 3 - p - q;
  plan.piece.corners = {c[p], c[q], c[r]};
  const auto& o = plan.piece.corners;
  const EdgeMeasure base_m = m[base];
  const EdgeMeasure left = measure(view, o[0], o[2]), right = measure(view, o[1], o[2]);
  const double ratio = std::max({base_m.depth_ratio, left.depth_ratio, right.depth_ratio});
  const double side = limits.side_px;
  plan.edge_rate = {rate_for(base_m.length_px * base_m.depth_ratio, side),
                    rate_for(left.length_px * left.depth_ratio, side),
                    rate_for(right.length_px * right.depth_ratio, side)};
  plan.flipped = {before(o[1], o[0]), before(o[2], o[0]), before(o[2], o[1])};
  // Rows shrink towards the apex and columns are no longer than the longer side, so the base and
  // the longer side (at the triangle's depth ratio) bound every step of the lattice.
  plan.depth_ratio = ratio;
  plan.nu = std::max(plan.edge_rate[0], rate_for(base_m.length_px * ratio, side));
  plan.nv = std::max({plan.edge_rate[1], plan.edge_rate[2],
                      rate_for(std::max(left.length_px, right.length_px) * ratio, side)});
  return plan;
}

bool DicePlan::too_large() const {
  return depth_ratio > kMaxDepthRatio || (long long)nu * nv > kMaxLattice;
}

LatticePoint lattice_point(const DicePlan& plan, int i, int j) {
  const auto& c = plan.piece.corners;
  if (j >= plan.nv) return c[2];
  if (j == 0) return edge_point(c[0], c[1], plan.edge_rate[0], plan.flipped[0], i, plan.nu);
  if (i == 0) return edge_point(c[0], c[2], plan.edge_rate[1], plan.flipped[1], j, plan.nv);
  if (i >= plan.nu) return edge_point(c[1], c[2], plan.edge_rate[2], plan.flipped[2], j, plan.nv);
  const double u = double(i) / plan.nu, v = double(j) / plan.nv;
  return lerp(lerp(c[0], c[1], u), c[2], v);
}

std::array<int, 2> block_cells(int grid_size, int nu, int nv) {
  const int g = std::max(1, int(std::sqrt(double(grid_size))));
  int bu = std::min(nu, g), bv = std::min(nv, g);
  if (bu < g) bv = std::min(nv, std::max(1, grid_size / bu));
  if (bv < g) bu = std::min(nu, std::max(1, grid_size / bv));
  return {bu, bv};
}

void cut_blocks(const FrameView& view, const DicePlan& plan, uint32_t plan_index,
                const DiceLimits& limits, std::vector<Block>& blocks) {
  const std::array<int, 2> cells = block_cells(limits.grid_size, plan.nu, plan.nv);
  const int bu = cells[0], bv = cells[1];
  for (int j0 = 0; j0 < plan.nv; j0 += bv)
    for (int i0 = 0; i0 < plan.nu; i0 += bu) {
      Block b{.plan = plan_index,
              .i0 = i0,
              .i1 = std::min(plan.nu, i0 + bu),
              .j0 = j0,
              .j1 = std::min(plan.nv, j0 + bv),
              .bounds = {},
              .depth_min = 0};
      double d0 = 1e300, d1 = 0;
      auto cover = [&](int i, int j) {
        const LatticePoint l = lattice_point(plan, i, j);
        for (const Point3d& p : {l.open, l.close}) {
          const Point2d r = view.project(p);
          b.bounds.add(r.x, r.y);
          d0 = std::min(d0, FrameView::depth(p));
          d1 = std::max(d1, FrameView::depth(p));
        }
      };
      for (int i = b.i0; i <= b.i1; ++i) cover(i, b.j0), cover(i, b.j1);
      for (int j = b.j0 + 1; j < b.j1; ++j) cover(b.i0, j), cover(b.i1, j);
      if (view.defocused()) b.bounds.grow(view.max_lens_shift_px(d0, d1));
      b.depth_min = d0;
      blocks.push_back(b);
    }
}

EyeVerdict eye_verdict(const FrameView& view, const Piece& piece, double margin_px) {
  std::vector<Point3d> points;
  points.reserve(6);
  for (const LatticePoint& c : piece.corners) points.push_back(c.open), points.push_back(c.close);
  return eye_verdict(view, points, margin_px);
}

EyeVerdict eye_verdict(const FrameView& view, const std::vector<Point3d>& points,
                       double margin_px) {
  if (!view.perspective()) return EyeVerdict::kInFront;
  const size_t n = points.size();
  size_t in_front = 0, behind = 0, beyond = 0;
  for (const Point3d& p : points) {
    const double d = FrameView::depth(p);
    in_front += d >= view.near_m();
    behind += d < view.near_m();
    beyond += d > view.far_m();
  }
  if (in_front == n) return beyond == n ? EyeVerdict::kBehind : EyeVerdict::kInFront;
  if (behind == n) return EyeVerdict::kBehind;
  // Beyond one side plane of the frustum (through the eye, so valid on both sides of it). The
  // lens widens what is seen near the eye: no side test with depth of field.
  if (!view.defocused()) {
    double x0, x1, y0, y1;
    view.window_bounds(margin_px, x0, x1, y0, y1);
    size_t out[4] = {0, 0, 0, 0};
    for (const Point3d& p : points) {
      const double d = FrameView::depth(p);
      out[0] += p.x<x0 * d, out[1] += p.x> x1 * d;
      out[2] += p.y<y0 * d, out[3] += p.y> y1 * d;
    }
    for (size_t k : out)
      if (k == n) return EyeVerdict::kOutside;
  }
  return EyeVerdict::kStraddles;
}

std::array<Piece, 4> split_in_four(const Piece& piece) {
  const auto& c = piece.corners;
  // Symmetric in the endpoints (a sum is commutative), so that a neighbour splitting the same
  // edge from its other end makes the very same midpoint.
  auto mid = [](const LatticePoint& a, const LatticePoint& b) {
    auto half = [](Point3d p, Point3d q) {
      return Point3d((p.x + q.x) * 0.5, (p.y + q.y) * 0.5, (p.z + q.z) * 0.5);
    };
    return LatticePoint{half(a.open, b.open), half(a.close, b.close),
                        Point2d((a.bary.x + b.bary.x) * 0.5, (a.bary.y + b.bary.y) * 0.5)};
  };
  const LatticePoint m01 = mid(c[0], c[1]), m12 = mid(c[1], c[2]), m20 = mid(c[2], c[0]);
  auto make = [&](const LatticePoint& a, const LatticePoint& b, const LatticePoint& d) {
    return Piece{piece.instance, piece.triangle, {a, b, d}};
  };
  return {make(c[0], m01, m20), make(m01, c[1], m12), make(m20, m12, c[2]), make(m01, m12, m20)};
}

}  // namespace obscura::reyes
