#include "obscura/reyes/sphere_patches.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "obscura/reyes/vertex_shading.h"

namespace obscura::reyes {

namespace {

constexpr double kPi = std::numbers::pi;
// Chords an edge's curve is measured with.
constexpr int kChords = 8;

int rate_for(double length_px, double side_px) {
  const double n = std::ceil(length_px / side_px);
  if (!(n < kMaxLatticeRate)) return kMaxLatticeRate;  // NaN too
  return std::max(1, int(n));
}

// The parameter i of n along an edge from a to b of rate e: snapped to the edge's own points
// (k of e), the ends returned exactly, so that both patches sharing the edge compute the same.
double edge_parameter(double a, double b, int e, int i, int n) {
  const long long k = (2LL * i * e + n) / (2LL * n);
  if (k <= 0) return a;
  if (k >= e) return b;
  return a + (b - a) * (double(k) / e);
}

Point3d object_point(const SphereFrame& s, double u, double v) {
  const Point3d d = sphere_direction(u, v);
  return {s.center.x + s.radius * d.x, s.center.y + s.radius * d.y, s.center.z + s.radius * d.z};
}

// The displacement at (u, v): at the seam's and the poles' one canonical (u, v).
double displacement_at(const SphereFrame& s, double u, double v) {
  if (!s.displacement->texture) return s.displacement->scale;
  if (u >= 1 || v <= 0 || v >= 1) u = 0;  // the seam is u = 0; at a pole, every u is u = 0
  return s.displacement->at(Point2f(float(u), float(v)));
}

Point3d displaced(const Transform& camera_from_object, Point3d p, Point3d direction, double h) {
  const Point3d q = camera_from_object(p);
  const Normal3d n = camera_from_object(Normal3d(direction.x, direction.y, direction.z));
  const double k = h / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  return {q.x + n.x * k, q.y + n.y * k, q.z + n.z * k};
}

LatticePoint lattice_at(const SphereFrame& s, double u, double v) {
  const Point3d p = object_point(s, u, v);
  if (!s.displacement) return {s.camera_from_object_open(p), s.camera_from_object_close(p), {u, v}};
  const Point3d d = sphere_direction(u, v);
  const double h = displacement_at(s, u, v);
  return {displaced(s.camera_from_object_open, p, d, h),
          displaced(s.camera_from_object_close, p, d, h),
          {u, v}};
}

Point3d at_shading_time(const FrameView& view, const LatticePoint& p) {
  return p.open + (p.close - p.open) * view.motion_fraction(view.shading_time_s());
}

// The rate of the curve from (ua, va) to (ub, vb): its largest projected chord of kChords, times
// kChords, in steps of at most the micropolygon's side. It depends on the curve alone.
int curve_rate(const FrameView& view, const SphereFrame& s, double ua, double va, double ub,
               double vb, double side_px) {
  double longest = 0;
  Point2d last = view.project(at_shading_time(view, lattice_at(s, ua, va)));
  for (int k = 1; k <= kChords; ++k) {
    const double t = double(k) / kChords;
    const Point2d next =
        view.project(at_shading_time(view, lattice_at(s, ua + (ub - ua) * t, va + (vb - va) * t)));
    longest = std::max(longest, std::hypot(next.x - last.x, next.y - last.y));
    last = next;
  }
  return rate_for(longest * kChords, side_px);
}

PatchPlan plan_patch(const FrameView& view, const SphereFrame& s, uint32_t sphere_index,
                     const PatchRect& r, double side_px) {
  PatchPlan plan;
  plan.sphere = sphere_index;
  plan.rect = r;
  plan.edge_rate = {curve_rate(view, s, r.u0, r.v0, r.u1, r.v0, side_px),
                    curve_rate(view, s, r.u0, r.v1, r.u1, r.v1, side_px),
                    curve_rate(view, s, r.u0, r.v0, r.u0, r.v1, side_px),
                    curve_rate(view, s, r.u1, r.v0, r.u1, r.v1, side_px)};
  plan.nu = std::max(plan.edge_rate[0], plan.edge_rate[1]);
  plan.nv = std::max(plan.edge_rate[2], plan.edge_rate[3]);
  // Inside, a parallel may be longer than both edges (across the equator) and a meridian nearer.
  for (double t : {0.25, 0.5, 0.75}) {
    const double v = r.v0 + (r.v1 - r.v0) * t, u = r.u0 + (r.u1 - r.u0) * t;
    plan.nu = std::max(plan.nu, curve_rate(view, s, r.u0, v, r.u1, v, side_px));
    plan.nv = std::max(plan.nv, curve_rate(view, s, u, r.v0, u, r.v1, side_px));
  }
  return plan;
}

// The range of sin (cos: shifted by π/2) over [a, b] (radians, b − a ≤ 2π).
void sine_range(double a, double b, double& lo, double& hi) {
  lo = std::min(std::sin(a), std::sin(b)), hi = std::max(std::sin(a), std::sin(b));
  // The extremes at π/2 + kπ inside the interval.
  for (double k = std::ceil((a - kPi / 2) / kPi); kPi / 2 + k * kPi <= b; k += 1) {
    const double x = std::sin(kPi / 2 + k * kPi);
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
}

// The corners of a box holding the patch (object space, exact ranges of each coordinate over
// the parameters), in camera space at both exposure ends: the patch and every micropolygon
// diced from it (flat between points of it) lie in their convex hull.
std::vector<Point3d> patch_hull(const SphereFrame& s, const PatchRect& r) {
  const double t0 = kPi * r.v0, t1 = kPi * r.v1, p0 = 2 * kPi * r.u0, p1 = 2 * kPi * r.u1;
  double st0, st1, sp0, sp1, cp0, cp1;
  sine_range(t0, t1, st0, st1);
  st0 = std::max(st0, 0.0);
  sine_range(p0, p1, sp0, sp1);
  sine_range(p0 + kPi / 2, p1 + kPi / 2, cp0, cp1);  // cos φ = sin(φ + π/2)
  auto product = [](double a0, double a1, double b0, double b1, double& lo, double& hi) {
    const double v[4] = {a0 * b0, a0 * b1, a1 * b0, a1 * b1};
    lo = *std::min_element(v, v + 4), hi = *std::max_element(v, v + 4);
  };
  double x0, x1, z0, z1;
  product(st0, st1, sp0, sp1, x0, x1);
  product(st0, st1, cp0, cp1, z0, z1);
  const double y0 = std::cos(t1), y1 = std::cos(t0);
  const double slack = 1e-9;  // rounding of the points evaluated later
  // The box in camera space at each end (grown by the displacement's reach), by its corners.
  std::vector<Point3d> corners;
  corners.reserve(16);
  for (const Transform* t : {&s.camera_from_object_open, &s.camera_from_object_close}) {
    Point3d lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (int k = 0; k < 8; ++k) {
      const Point3d p = (*t)(Point3d(s.center.x + s.radius * ((k & 1) ? x1 + slack : x0 - slack),
                                     s.center.y + s.radius * ((k & 2) ? y1 + slack : y0 - slack),
                                     s.center.z + s.radius * ((k & 4) ? z1 + slack : z0 - slack)));
      lo = Point3d(std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z));
      hi = Point3d(std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z));
    }
    for (int k = 0; k < 8; ++k)
      corners.emplace_back((k & 1) ? hi.x + s.reach : lo.x - s.reach,
                           (k & 2) ? hi.y + s.reach : lo.y - s.reach,
                           (k & 4) ? hi.z + s.reach : lo.z - s.reach);
  }
  return corners;
}

RasterBounds hull_bounds(const FrameView& view, const std::vector<Point3d>& hull) {
  RasterBounds b;
  double d0 = 1e300, d1 = -1e300;
  for (const Point3d& p : hull) {
    const Point2d r = view.project(p);
    b.add(r.x, r.y);
    d0 = std::min(d0, FrameView::depth(p)), d1 = std::max(d1, FrameView::depth(p));
  }
  if (view.defocused()) b.grow(view.max_lens_shift_px(d0, d1));
  return b;
}

// Blocks of at most grid_size micropolygons (block_cells, as cut_blocks), bounded by every
// lattice vertex they hold (a curved patch bulges between its boundary vertices).
void cut_patch_blocks(const FrameView& view, const SphereFrame& s, const PatchPlan& plan,
                      uint32_t plan_index, const DiceLimits& limits, const RasterBounds& region,
                      std::vector<Block>& blocks) {
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
              .depth_min = 0,
              .sphere = true};
      double d0 = 1e300, d1 = 0;
      for (int j = b.j0; j <= b.j1; ++j)
        for (int i = b.i0; i <= b.i1; ++i) {
          const LatticePoint l = patch_point(s, plan, i, j);
          for (const Point3d& p : {l.open, l.close}) {
            const Point2d r = view.project(p);
            b.bounds.add(r.x, r.y);
            d0 = std::min(d0, FrameView::depth(p));
            d1 = std::max(d1, FrameView::depth(p));
          }
        }
      if (view.defocused()) b.bounds.grow(view.max_lens_shift_px(d0, d1));
      b.depth_min = d0;
      if (b.bounds.overlaps(region)) blocks.push_back(b);
    }
}

std::array<PatchRect, 4> split_rect_in_four(const PatchRect& r) {
  const double um = (r.u0 + r.u1) * 0.5, vm = (r.v0 + r.v1) * 0.5;
  return {PatchRect{r.u0, um, r.v0, vm}, PatchRect{um, r.u1, r.v0, vm},
          PatchRect{r.u0, um, vm, r.v1}, PatchRect{um, r.u1, vm, r.v1}};
}

// One attempt at cutting the sphere into rows × 2·rows patches; false (and `out` untouched)
// when a patch's lattice is too large for that many rows (planning is cheap: the lattices are
// evaluated only once every patch fits).
bool split_uniformly(const FrameView& view, const SphereFrame& s, uint32_t sphere_index, int rows,
                     const DiceLimits& limits, int eye_split_limit, const RasterBounds& region,
                     double margin_px, PatchSplit& out) {
  struct Pending {
    PatchRect rect;
    int eye_level = 0;
  };
  PatchSplit local;
  std::vector<PatchPlan> planned;
  std::vector<Pending> stack;
  const int columns = 2 * rows;
  for (int row = rows - 1; row >= 0; --row)  // pushed in reverse: planned in row order
    for (int column = columns - 1; column >= 0; --column)
      stack.push_back({PatchRect{double(column) / columns, double(column + 1) / columns,
                                 double(row) / rows, double(row + 1) / rows},
                       0});
  while (!stack.empty()) {
    const Pending next = stack.back();
    stack.pop_back();
    const std::vector<Point3d> hull = patch_hull(s, next.rect);
    switch (eye_verdict(view, hull, margin_px)) {
      case EyeVerdict::kBehind:
      case EyeVerdict::kOutside:
        continue;
      case EyeVerdict::kStraddles:
        if (next.eye_level >= eye_split_limit) {
          ++local.eye_split_culled;
          continue;
        }
        ++local.eye_splits;
        {
          const std::array<PatchRect, 4> children = split_rect_in_four(next.rect);
          for (auto c = children.rbegin(); c != children.rend(); ++c)
            stack.push_back({*c, next.eye_level + 1});
        }
        continue;
      case EyeVerdict::kInFront:
        break;
    }
    // Every patch in the frame's view decides the rows, whether or not it reaches `region` (a
    // crop window or a bucket): the sphere is diced alike for every region of the frame.
    const PatchPlan plan = plan_patch(view, s, sphere_index, next.rect, limits.side_px);
    if ((long long)plan.nu * plan.nv > kMaxLattice && rows < kMaxPatchRows) return false;
    if (hull_bounds(view, hull).overlaps(region)) planned.push_back(plan);
  }
  // Every patch dices at these rows: cut the lattices into blocks.
  for (const PatchPlan& plan : planned) {
    ++local.pieces;
    const size_t before = local.blocks.size();
    cut_patch_blocks(view, s, plan, uint32_t(local.plans.size()), limits, region, local.blocks);
    if (local.blocks.size() > before) local.plans.push_back(plan);
  }
  out = std::move(local);
  return true;
}

}  // namespace

Point3d sphere_direction(double u, double v) {
  if (v <= 0) return {0, 1, 0};
  if (v >= 1) return {0, -1, 0};
  if (u >= 1) u -= 1;  // the seam: u = 1 is u = 0, to the bit
  const double theta = kPi * v, phi = 2 * kPi * u;
  const double s = std::sin(theta);
  return {s * std::sin(phi), std::cos(theta), s * std::cos(phi)};
}

LatticePoint patch_point(const SphereFrame& sphere, const PatchPlan& plan, int i, int j) {
  const PatchRect& r = plan.rect;
  double u, v;
  if (j == 0) {
    u = edge_parameter(r.u0, r.u1, plan.edge_rate[0], i, plan.nu), v = r.v0;
  } else if (j >= plan.nv) {
    u = edge_parameter(r.u0, r.u1, plan.edge_rate[1], i, plan.nu), v = r.v1;
  } else if (i == 0) {
    u = r.u0, v = edge_parameter(r.v0, r.v1, plan.edge_rate[2], j, plan.nv);
  } else if (i >= plan.nu) {
    u = r.u1, v = edge_parameter(r.v0, r.v1, plan.edge_rate[3], j, plan.nv);
  } else {
    u = r.u0 + (r.u1 - r.u0) * (double(i) / plan.nu);
    v = r.v0 + (r.v1 - r.v0) * (double(j) / plan.nv);
  }
  return lattice_at(sphere, u, v);
}

void split_sphere(const FrameView& view, const SphereFrame& sphere, uint32_t sphere_index,
                  const DiceLimits& limits, int eye_split_limit, const RasterBounds& region,
                  double margin_px, PatchSplit& out) {
  PatchSplit mine;
  for (int rows = 2;; rows *= 2)
    if (split_uniformly(view, sphere, sphere_index, rows, limits, eye_split_limit, region,
                        margin_px, mine))
      break;
  const uint32_t offset = uint32_t(out.plans.size());
  for (Block& b : mine.blocks) b.plan += offset;
  out.plans.insert(out.plans.end(), mine.plans.begin(), mine.plans.end());
  out.blocks.insert(out.blocks.end(), mine.blocks.begin(), mine.blocks.end());
  out.pieces += mine.pieces;
  out.eye_splits += mine.eye_splits;
  out.eye_split_culled += mine.eye_split_culled;
}

Grid dice_and_shade_patch(const ReyesScene& scene, const FrameView& view, const SphereFrame& sphere,
                          const PatchPlan& plan, const Block& block, uint64_t key,
                          GridCounts& counts) {
  const Scene& s = scene.scene();
  const Instance& inst = s.instances[sphere.instance];
  const Transform world_from_object =
      scene.motion().world_from_object(sphere.instance, view.shading_time_s());
  const shading::SurfaceMaterial& m = scene.material(s.material_of(inst));
  Grid g = start_grid(block, key, sphere.instance, kAnalyticSurface, m, view.moves());
  uint64_t overruns = 0;  // vertices displaced beyond the bound
  for (int j = block.j0; j <= block.j1; ++j)
    for (int i = block.i0; i <= block.i1; ++i) {
      const LatticePoint lp = patch_point(sphere, plan, i, j);
      g.open.push_back(lp.open);
      if (view.moves()) g.close.push_back(lp.close);
      const Point3d d = sphere_direction(lp.bary.x, lp.bary.y);
      const Point3d object = object_point(sphere, lp.bary.x, lp.bary.y);
      const Point3d w = sphere.displacement
                            ? displaced(world_from_object, object, d,
                                        displacement_at(sphere, lp.bary.x, lp.bary.y))
                            : world_from_object(object);
      if (sphere.displacement &&
          std::abs(displacement_at(sphere, lp.bary.x, lp.bary.y)) > sphere.displacement->bound)
        ++overruns;
      const Normal3d nw = world_from_object(Normal3d(d.x, d.y, d.z));
      const double l = std::sqrt(nw.x * nw.x + nw.y * nw.y + nw.z * nw.z);
      VertexSurface vs;
      vs.position = w;
      // Outward: the inverse transpose keeps a normal on the side it was on.
      vs.true_normal = Vector3f(float(nw.x / l), float(nw.y / l), float(nw.z / l));
      vs.shading_normal = vs.true_normal;
      vs.uv[0] = Point2f(float(lp.bary.x), float(lp.bary.y));
      shade_vertex(scene, view, m, vs, g);
    }
  finish_grid(view, g, counts);
  counts.displacement_overruns += overruns;
  return g;
}

}  // namespace obscura::reyes
