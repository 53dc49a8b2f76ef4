#include "obscura/reyes/hider.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "obscura/camera/pixel_filter.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/math/sampler.h"
#include "obscura/reyes/reyes_scene.h"

namespace obscura::reyes {

namespace {

// The edge function of u → v at p (twice the signed area of u, v, p), evaluated from the
// endpoints in canonical order so that v → u gives exactly its negation.
double edge(Point2d u, Point2d v, double px, double py) {
  const bool swap = v.x < u.x || (v.x == u.x && v.y < u.y);
  const Point2d& a = swap ? v : u;
  const Point2d& b = swap ? u : v;
  const double e = (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
  return swap ? -e : e;
}

// Whether a sample exactly on edge u → v (of a triangle turned positively) belongs to it: the
// neighbour across the edge runs it v → u, so exactly one of the two owns it.
bool owns(Point2d u, Point2d v, bool reversed) {
  double dx = v.x - u.x, dy = v.y - u.y;
  if (reversed) dx = -dx, dy = -dy;
  return dy > 0 || (dy == 0 && dx < 0);
}

}  // namespace

// A micropolygon triangle set up for many samples: its edges in canonical order (the same
// doubles edge() computes) with the sign that turns the triangle positive, and which of them
// own a sample lying exactly on them.
BucketHider::Triangle BucketHider::set_up(Point2d a, Point2d b, Point2d c) {
  Triangle t;
  t.area = edge(a, b, c.x, c.y);
  t.valid = t.area != 0 && std::isfinite(t.area);
  if (!t.valid) return t;
  const bool reversed = t.area < 0;
  if (reversed) t.area = -t.area;
  const Point2d from[3] = {b, c, a}, to[3] = {c, a, b};
  for (int k = 0; k < 3; ++k) {
    const Point2d u = from[k], v = to[k];
    const bool swap = v.x < u.x || (v.x == u.x && v.y < u.y);
    const Point2d& p = swap ? v : u;
    const Point2d& q = swap ? u : v;
    t.edges[k] = {p.x, p.y, q.x - p.x, q.y - p.y, swap != reversed, owns(u, v, reversed)};
  }
  return t;
}

bool BucketHider::inside(const Triangle& t, double px, double py, double w[3]) {
  if (!t.valid) return false;
  double e[3];
  for (int k = 0; k < 3; ++k) {
    const Edge& d = t.edges[k];
    const double f = d.dx * (py - d.y) - d.dy * (px - d.x);
    e[k] = d.negate ? -f : f;
    if (e[k] < 0 || (e[k] == 0 && !d.owned)) return false;
  }
  w[0] = e[0] / t.area, w[1] = e[1] / t.area, w[2] = e[2] / t.area;
  return true;
}

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace

BucketHider::BucketHider(const FrameView& view, const CameraSampleOrder& order,
                         const ReyesSettings& settings, Bounds2i pixels, Point2i crop_min)
    : view_(view), pixels_(pixels), crop_min_(crop_min), per_pixel_(settings.pixel_samples) {
  const size_t count = size_t(pixels.area()) * size_t(per_pixel_);
  samples_.reserve(count);
  for (int y = pixels.min.y; y < pixels.max.y; ++y)
    for (int x = pixels.min.x; x < pixels.max.x; ++x) {
      // Random numbers are keyed on the full image's pixel, as in the tracer.
      const Point2i pixel{x + crop_min.x, y + crop_min.y};
      const double delay = order.pixel_delay_s(pixel);
      SobolPixelKeys keys(settings.seed, pixel);  // the same numbers, hashed once per pixel
      for (int s = 0; s < per_pixel_; ++s) {
        Sampler sampler = settings.sampler == SamplerType::kSobol
                              ? Sampler(settings.sampler, settings.seed, pixel, uint32_t(s), keys)
                              : Sampler(settings.sampler, settings.seed, pixel, uint32_t(s));
        const CameraSample cs = order.draw(sampler, pixel, delay);
        SamplePoint p;
        p.x = cs.film_point.x, p.y = cs.film_point.y;
        p.time_s = cs.time_s;
        p.tau = view.motion_fraction(cs.time_s);
        p.lens_u = cs.lens;
        p.lens_m = view.lens_offset(cs.lens);
        p.weight = float(cs.filter_weight);
        bounds_.add(p.x, p.y);
        margin_px_ = std::max(
            {margin_px_, pixel.x - p.x, p.x - (pixel.x + 1), pixel.y - p.y, p.y - (pixel.y + 1)});
        samples_.push_back(p);
      }
    }
  if (view.moves()) {
    // Each pixel's samples in order of time (ties by index), for the moving micropolygons.
    by_time_.resize(count);
    for (size_t i = 0; i < count; ++i) by_time_[i] = uint32_t(i);
    for (size_t first = 0; first < count; first += size_t(per_pixel_))
      std::sort(by_time_.begin() + long(first), by_time_.begin() + long(first) + per_pixel_,
                [&](uint32_t a, uint32_t b) {
                  return samples_[a].tau != samples_[b].tau ? samples_[a].tau < samples_[b].tau
                                                            : a < b;
                });
  }
  nearest_.assign(count, Visible{.depth = kInfinity});
  opaque_hit_.assign(count, 0);
}

void BucketHider::set_up_quad(const Corner corners[4], Triangle triangles[2]) {
  triangles[0] = set_up(corners[0].r, corners[1].r, corners[2].r);
  triangles[1] = set_up(corners[0].r, corners[2].r, corners[3].r);
}

bool BucketHider::hides(double depth) {
  if (opaque_count_ < samples_.size()) return false;
  if (!farthest_known_) {
    farthest_ = 0;
    for (const Visible& v : nearest_) farthest_ = std::max(farthest_, v.depth);
    farthest_known_ = true;
  }
  return farthest_ < depth;
}

void BucketHider::sample(const Grid& g, HiderCounts& counts) {
  const int row = g.row();
  const bool still = !g.raster.empty();
  const bool moves = !g.close.empty();
  const int x_min = pixels_.min.x + crop_min_.x, y_min = pixels_.min.y + crop_min_.y;
  const int x_max = pixels_.max.x + crop_min_.x, y_max = pixels_.max.y + crop_min_.y;
  const int width = pixels_.width();
  Corner corners[4];
  Triangle triangles[2];
  RasterBounds b_open, b_close;
  double slack = 0, k0 = 0, k1 = 0,
         lens_grow = 0;  // the thin lens's factor at the nearest and farthest depth
  const double sx = view_.raster_scale_x(), sy = view_.raster_scale_y();
  for (int j = 0; j < g.nv; ++j)
    for (int i = 0; i < g.nu; ++i) {
      const int index[4] = {j * row + i, j * row + i + 1, (j + 1) * row + i + 1, (j + 1) * row + i};
      RasterBounds b;
      if (still) {
        for (int k = 0; k < 4; ++k) {
          corners[k] = {g.raster[size_t(index[k])], FrameView::depth(g.open[size_t(index[k])])};
          b.add(corners[k].r.x, corners[k].r.y);
        }
      } else {
        // Its bounds at the exposure's two ends; at a time between, the image of each corner
        // strays from the straight line between its ends by at most ¼ × its travel × its
        // relative change of depth (a projection is a ratio of linear functions of time).
        b_open = {}, b_close = {};
        slack = 1e-6;  // rounding
        double d0 = 1e300, d1 = -1e300;
        for (int k = 0; k < 4; ++k) {
          const Point3d po = g.open[size_t(index[k])];
          const Point3d pc = moves ? g.close[size_t(index[k])] : po;
          const Point2d ro = view_.project(po), rc = moves ? view_.project(pc) : ro;
          b_open.add(ro.x, ro.y), b_close.add(rc.x, rc.y);
          const double dop = FrameView::depth(po), dcl = FrameView::depth(pc);
          d0 = std::min({d0, dop, dcl}), d1 = std::max({d1, dop, dcl});
          if (moves && view_.perspective())
            slack = std::max(slack, 0.25 * std::max(std::abs(rc.x - ro.x), std::abs(rc.y - ro.y)) *
                                        std::abs(dcl - dop) / std::min(dop, dcl));
        }
        b = b_open;
        b.add(b_close.x0, b_close.y0), b.add(b_close.x1, b_close.y1);
        k0 = view_.lens_factor(d0), k1 = view_.lens_factor(d1);
        lens_grow = view_.max_lens_shift_px(d0, d1);
        if (view_.defocused()) b.grow(lens_grow);
      }
      if (b.empty() || !b.overlaps(bounds_)) continue;
      if (still) set_up_quad(corners, triangles);
      const int px0 = std::max(x_min, int(std::floor(b.x0 - margin_px_)));
      const int px1 = std::min(x_max - 1, int(std::floor(b.x1 + margin_px_)));
      const int py0 = std::max(y_min, int(std::floor(b.y0 - margin_px_)));
      const int py1 = std::min(y_max - 1, int(std::floor(b.y1 + margin_px_)));
      const uint32_t micropolygon = uint32_t(j * g.nu + i);
      for (int py = py0; py <= py1; ++py)
        for (int px = px0; px <= px1; ++px) {
          const size_t first = (size_t(py - y_min) * width + size_t(px - x_min)) * per_pixel_;
          // Moving: only the samples whose time finds the micropolygon over this pixel (its
          // pixel's samples are kept sorted by time), else every sample of the pixel.
          size_t k = first, k_end = first + size_t(per_pixel_);
          if (!by_time_.empty() && moves) {
            const double grow = slack + lens_grow;
            double t0 = 0, t1 = 1;
            auto below = [&](double a, double b, double c) {  // keep t with a + b·t ≤ c
              if (b > 0)
                t1 = std::min(t1, (c - a) / b);
              else if (b < 0)
                t0 = std::max(t0, (c - a) / b);
              else if (a > c)
                t1 = -1;
            };
            below(b_open.x0 - grow, b_close.x0 - b_open.x0, px + 1 + margin_px_);
            below(-(b_open.x1 + grow), -(b_close.x1 - b_open.x1), -(px - margin_px_));
            below(b_open.y0 - grow, b_close.y0 - b_open.y0, py + 1 + margin_px_);
            below(-(b_open.y1 + grow), -(b_close.y1 - b_open.y1), -(py - margin_px_));
            constexpr double kEps = 1e-9;  // rounding: never drop a sample at the interval's end
            const auto begin = by_time_.begin() + long(first), end = begin + per_pixel_;
            const auto lo = std::lower_bound(
                begin, end, t0 - kEps, [&](uint32_t i, double t) { return samples_[i].tau < t; });
            const auto hi = std::upper_bound(
                lo, end, t1 + kEps, [&](double t, uint32_t i) { return t < samples_[i].tau; });
            k = size_t(lo - by_time_.begin()), k_end = size_t(hi - by_time_.begin());
          }
          for (; k < k_end; ++k) {
            const size_t s = by_time_.empty() || !moves ? k : by_time_[k];
            const SamplePoint& sp = samples_[s];
            if (sp.x < b.x0 || sp.x > b.x1 || sp.y < b.y0 || sp.y > b.y1) continue;
            if (!still) {
              // Where the micropolygon can be at this sample's time, shifted by this sample's
              // lens point at the micropolygon's depths (the shift is monotonic in depth).
              const double t = sp.tau;
              double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
              if (view_.defocused()) {
                const double xa = sx * sp.lens_m.x * k0, xb = sx * sp.lens_m.x * k1;
                const double ya = sy * sp.lens_m.y * k0, yb = sy * sp.lens_m.y * k1;
                x_lo = std::min(xa, xb), x_hi = std::max(xa, xb);
                y_lo = std::min(ya, yb), y_hi = std::max(ya, yb);
              }
              if (sp.x < b_open.x0 + (b_close.x0 - b_open.x0) * t - slack + x_lo ||
                  sp.x > b_open.x1 + (b_close.x1 - b_open.x1) * t + slack + x_hi ||
                  sp.y < b_open.y0 + (b_close.y0 - b_open.y0) * t - slack + y_lo ||
                  sp.y > b_open.y1 + (b_close.y1 - b_open.y1) * t + slack + y_hi)
                continue;
            }
            if (!still)
              for (int k = 0; k < 4; ++k) {
                Point3d p = g.open[size_t(index[k])];
                if (moves) p = p + (g.close[size_t(index[k])] - p) * sp.tau;
                const double d = FrameView::depth(p);
                Point2d r = view_.project(p);
                if (view_.defocused()) {
                  const Point2d shift = view_.lens_shift(sp.lens_m, d);
                  r = {r.x + shift.x, r.y + shift.y};
                }
                corners[k] = {r, d};
              }
            if (!still) set_up_quad(corners, triangles);
            test(g, micropolygon, corners, triangles, index, uint32_t(s), sp, counts);
          }
        }
    }
}

void BucketHider::test(const Grid& g, uint32_t micropolygon, const Corner corners[4],
                       const Triangle triangles[2], const int index[4], uint32_t sample,
                       const SamplePoint& s, HiderCounts& counts) {
  ++counts.tested;
  static constexpr int kTriangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (int k = 0; k < 2; ++k) {
    const int* t = kTriangles[k];
    double w[3];
    if (!inside(triangles[k], s.x, s.y, w)) continue;
    const double depth =
        w[0] * corners[t[0]].depth + w[1] * corners[t[1]].depth + w[2] * corners[t[2]].depth;
    if (!(depth >= view_.near_m() && depth <= view_.far_m())) return;
    const size_t v[3] = {size_t(index[t[0]]), size_t(index[t[1]]), size_t(index[t[2]])};
    float alpha = 1;
    if (g.coverage != Coverage::kOpaque) {
      alpha = float(w[0] * g.alpha[v[0]] + w[1] * g.alpha[v[1]] + w[2] * g.alpha[v[2]]);
      if (g.coverage == Coverage::kMask && !(alpha >= g.alpha_cutoff)) return;
      if (g.coverage == Coverage::kBlend && !(alpha > 0)) return;
    }
    if (g.coverage != Coverage::kBlend && !(depth < nearest_[sample].depth)) return;
    ++counts.hit;
    Visible point;
    point.depth = float(depth);
    point.color =
        g.color[v[0]] * float(w[0]) + g.color[v[1]] * float(w[1]) + g.color[v[2]] * float(w[2]);
    point.normal =
        g.normal[v[0]] * float(w[0]) + g.normal[v[1]] * float(w[1]) + g.normal[v[2]] * float(w[2]);
    point.mesh = g.mesh;
    point.surface = {int32_t(g.instance), g.triangle};
    // The distance along the sample's ray, from its lens point.
    Point3d p(0, 0, 0);
    for (int k = 0; k < 3; ++k) {
      Point3d c = g.open[v[k]];
      if (!g.close.empty()) c = c + (g.close[v[k]] - c) * s.tau;
      p = p + (c - Point3d(0, 0, 0)) * w[k];
    }
    const Vector3d from_lens =
        view_.perspective() ? p - Point3d(s.lens_m.x, s.lens_m.y, 0) : Vector3d(0, 0, p.z);
    point.range = float(length(from_lens));
    if (g.coverage == Coverage::kBlend) {
      fragments_.push_back({sample, std::min(alpha, 1.f), g.key, micropolygon, point});
    } else {
      nearest_[sample] = point;
      opaque_count_ += opaque_hit_[sample] == 0;
      opaque_hit_[sample] = 1;
      farthest_known_ = false;
    }
    return;
  }
}

void BucketHider::resolve(const ReyesScene& scene, const PreparedCamera& camera, bool needs_rays,
                          float exposure, Film& film, AovBuffers* aovs,
                          std::vector<SeenTriangle>* seen) {
  std::sort(fragments_.begin(), fragments_.end(), [](const Fragment& a, const Fragment& b) {
    if (a.sample != b.sample) return a.sample < b.sample;
    if (a.point.depth != b.point.depth) return a.point.depth < b.point.depth;
    if (a.key != b.key) return a.key < b.key;
    return a.micropolygon < b.micropolygon;
  });
  size_t f = 0;
  size_t s = 0;
  for (int y = pixels_.min.y; y < pixels_.max.y; ++y)
    for (int x = pixels_.min.x; x < pixels_.max.x; ++x)
      for (int k = 0; k < per_pixel_; ++k, ++s) {
        const SamplePoint& sp = samples_[s];
        const bool opaque = opaque_hit_[s] != 0;
        const float behind = opaque ? nearest_[s].depth : kInfinity;
        Rgb c;
        float transmitted = 1;
        const Visible* first = nullptr;
        for (; f < fragments_.size() && fragments_[f].sample == s; ++f) {
          const Fragment& fr = fragments_[f];
          if (!(fr.point.depth < behind) || transmitted <= 0) continue;
          c += fr.point.color * (transmitted * fr.alpha);
          transmitted *= 1 - fr.alpha;
          if (!first) first = &fr.point;
        }
        if (opaque) {
          c += nearest_[s].color * transmitted;
          if (!first) first = &nearest_[s];
        }
        float ray_weight = 1;
        if (needs_rays) {
          const auto ray = camera.generate_ray({sp.x, sp.y}, {sp.lens_u.x, sp.lens_u.y}, sp.time_s);
          ray_weight = ray ? float(ray->weight) : 0.f;
          if (ray && !opaque && transmitted > 0)
            c += scene.background(ray->direction) * transmitted;
        }
        film.add_sample({x, y}, c * (exposure * ray_weight), sp.weight);
        if (seen && k == 0 && first)
          (*seen)[size_t(y) * size_t(film.width()) + size_t(x)] = first->surface;
        if (aovs) {
          const Vector3f n = first ? first->normal : Vector3f();
          aovs->add_sample({x, y}, first != nullptr, Rgb(), Normal3f(n.x, n.y, n.z),
                           first ? first->depth : 0.f, first ? first->range : 0.f,
                           first ? first->mesh : 0);
        }
      }
}

}  // namespace obscura::reyes
