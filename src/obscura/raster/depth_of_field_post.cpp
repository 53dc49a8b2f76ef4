#include "obscura/raster/depth_of_field_post.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "obscura/math/error.h"

namespace obscura::raster {

namespace {

constexpr int kTile = 16;  // pixels; the gather radius is chosen per tile
constexpr int kLanes = 8;  // samples gathered side by side (one AVX register of floats)
// Depth standing in for "nothing drawn" (+∞): far enough that its circle of confusion equals
// the formula's limit S → ∞ to 12 digits, finite so that depth differences stay numbers.
constexpr double kFarDepthM = 1e12;

// kLanes floats processed together (the GCC/Clang vector extension). The gather is compiled
// for the baseline ISA and for AVX2 and chosen at run time, as the tile rasterizer is; the
// arithmetic is the same IEEE operations on either path (no FMA contraction), so both give
// the same image. The helpers are always inlined: no vector crosses a call, so the ABI note
// GCC gives for 32-byte vector arguments without AVX does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"
using Lanes = float __attribute__((vector_size(kLanes * sizeof(float))));
[[gnu::always_inline]] inline Lanes load(const float* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline Lanes min_of(Lanes a, Lanes b) {
  return a < b ? a : b;
}
[[gnu::always_inline]] inline Lanes max_of(Lanes a, Lanes b) {
  return a > b ? a : b;
}
[[gnu::always_inline]] inline Lanes clamp01(Lanes v) {
  const Lanes zero = {};
  return min_of(max_of(v, zero), zero + 1.f);
}

double finite_depth(float d) {
  return std::isfinite(d) && d > 0 ? double(d) : kFarDepthM;
}

// Everything the gather reads, and where it writes.
struct Gather {
  int width, height, stride;
  float aspect, depth_tolerance;
  int tiles_x;
  const float *depth, *radius, *plane[3], *tile_reach, *distance;
  int distance_width, max_rx, max_ry;
  float* out;  // RGB, width × height
};

// One row of output pixels.
[[gnu::always_inline]] inline void gather_row(const Gather& g, int y) {
  const int w = g.width, h = g.height, stride = g.stride, tiles_x = g.tiles_x;
  const float aspect = g.aspect;
  const float* depth = g.depth;
  const float* radius = g.radius;
  const float* const* plane = g.plane;
  const float* tile_reach = g.tile_reach;
  const float* distance = g.distance;
  const int distance_width = g.distance_width, max_rx = g.max_rx, max_ry = g.max_ry;
  const Lanes zero = {}, one = zero + 1.f;
  Lanes lane_index = zero;
  for (int l = 0; l < kLanes; ++l) lane_index[l] = float(l);
  const float inv_area_scale = float(std::numbers::pi) * aspect;
  for (int x = 0; x < w; ++x) {
    const size_t p = size_t(y) * stride + x;
    const float z_p = depth[p], r_p = radius[p];
    const float inv_tolerance = 1 / float(g.depth_tolerance * z_p);
    const float reach = tile_reach[size_t(y / kTile) * tiles_x + x / kTile];
    const int rx = int(std::ceil(reach)), ry = int(std::ceil(reach * aspect));
    const int x0 = std::max(0, x - rx), x1 = std::min(w - 1, x + rx);
    // Per lane: weight and colour of the samples in front of p, and of p's own layer and
    // what lies behind it.
    Lanes front_w = zero, back_w = zero, front_c[3] = {zero, zero, zero},
          back_c[3] = {zero, zero, zero};
    const Lanes z_p_v = zero + z_p, r_p_v = zero + r_p;
    const float last = float(x1 - x);
    for (int qy = std::max(0, y - ry); qy <= std::min(h - 1, y + ry); ++qy) {
      const float* distance_row = &distance[size_t(qy - y + max_ry) * distance_width + max_rx];
      const size_t row = size_t(qy) * stride;
      for (int qx = x0; qx <= x1; qx += kLanes) {
        const size_t q = row + size_t(qx);
        // Lanes past the row's end read the padding and weigh 0.
        const Lanes valid = (lane_index + float(qx - x) <= last) ? one : zero;
        const Lanes d = load(distance_row + (qx - x));
        const Lanes z_q = load(&depth[q]), r_q = load(&radius[q]);
        const Lanes behind = clamp01((z_q - z_p_v) * inv_tolerance);
        const Lanes in_front = clamp01((z_p_v - z_q) * inv_tolerance);
        // Behind p, a sample spreads no farther than p's own blur.
        const Lanes r = max_of(r_q + behind * (min_of(r_q, r_p_v) - r_q), zero + 0.5f);
        const Lanes coverage = clamp01(r + 0.5f - d) * valid;
        const Lanes weight = coverage / max_of(inv_area_scale * r * r, one);
        const Lanes wf = in_front * weight, wb = weight - wf;
        front_w += wf;
        back_w += wb;
        for (int k = 0; k < 3; ++k) {
          const Lanes c = load(&plane[k][q]);
          front_c[k] += wf * c;
          back_c[k] += wb * c;
        }
      }
    }
    double fw = 0, bw = 0, fc[3] = {0, 0, 0}, bc[3] = {0, 0, 0};
    for (int l = 0; l < kLanes; ++l) {
      fw += front_w[l], bw += back_w[l];
      for (int k = 0; k < 3; ++k) fc[k] += front_c[k][l], bc[k] += back_c[k][l];
    }
    // p itself is always in the back layer with weight 1, so bw > 0.
    const double alpha = std::min(fw, 1.0);
    for (int k = 0; k < 3; ++k) {
      double b = bc[k] / bw;
      double f = fw > 0 ? fc[k] / fw : 0.0;
      g.out[(size_t(y) * w + x) * 3 + k] = float(alpha * f + (1 - alpha) * b);
    }
  }
}

[[gnu::flatten]] void gather_row_baseline(const Gather& g, int y) {
  gather_row(g, y);
}
#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2"), gnu::flatten]] void gather_row_avx2(const Gather& g, int y) {
  gather_row(g, y);
}
#endif

}  // namespace

Image circle_of_confusion_image(const Image& view_depth, const Camera& camera) {
  if (view_depth.channels != 1)
    throw Error("circle_of_confusion_image.view_depth",
                "must have one channel; got " + std::to_string(view_depth.channels));
  Image coc(view_depth.width, view_depth.height, 1);
  coc.channel_names = {"C"};
  const PreparedCamera prepared = camera.prepare();
  for (size_t i = 0; i < view_depth.data.size(); ++i)
    coc.data[i] = float(prepared.circle_of_confusion_px(finite_depth(view_depth.data[i])));
  return coc;
}

Image depth_of_field_post(const Image& color, const Image& view_depth, const Camera& camera,
                          const PostDepthOfFieldSettings& settings) {
  return depth_of_field_post(color, view_depth, circle_of_confusion_image(view_depth, camera),
                             camera.film.pixel_aspect, settings);
}

Image depth_of_field_post(const Image& color, const Image& view_depth, const Image& coc_px,
                          double pixel_aspect, const PostDepthOfFieldSettings& settings) {
  if (color.channels < 3)
    throw Error("depth_of_field_post.color",
                "needs at least 3 channels; got " + std::to_string(color.channels));
  if (view_depth.channels != 1 || view_depth.width != color.width ||
      view_depth.height != color.height)
    throw Error("depth_of_field_post.view_depth",
                "must be one channel of " + std::to_string(color.width) + "x" +
                    std::to_string(color.height) + "; got " + std::to_string(view_depth.channels) +
                    " channel(s) of " + std::to_string(view_depth.width) + "x" +
                    std::to_string(view_depth.height));
  if (coc_px.channels != 1 || coc_px.width != color.width || coc_px.height != color.height)
    throw Error("depth_of_field_post.coc_px", "must be one channel of the colour's size");
  // Bounded so that the gather's reach in rows (radius × aspect) and its offset table stay
  // small: a disk can only be that many pixels across.
  if (!(pixel_aspect >= 1.0 / 1024 && pixel_aspect <= 1024))
    throw Error("depth_of_field_post.pixel_aspect",
                "must be in [1/1024, 1024]; got " + std::to_string(pixel_aspect));
  if (!(settings.max_coc_px >= 0 && settings.max_coc_px <= 4096))
    throw Error("depth_of_field_post.max_coc_px",
                "must be in [0, 4096] pixels; got " + std::to_string(settings.max_coc_px));
  if (!(settings.depth_tolerance >= 1e-6 && settings.depth_tolerance <= 1e6))
    throw Error("depth_of_field_post.depth_tolerance",
                "must be in [1e-6, 1e6]; got " + std::to_string(settings.depth_tolerance));

  const int w = color.width, h = color.height;
  Image out(w, h, 3);
  out.channel_names = {"R", "G", "B"};

  // 1. Depth, blur radius and the disk's density (1 / area) per pixel, and the colour in planes,
  //    all in float for the gather's vector lanes. Radii are in horizontal pixels; with
  //    non-square pixels a disk is `aspect` times taller in pixel rows.
  const float aspect = float(pixel_aspect);
  const float max_radius = float(0.5 * settings.max_coc_px);
  // Rows are padded by kLanes pixels so that a row's last lanes read memory that exists.
  const int stride = w + kLanes;
  const size_t n = size_t(stride) * h;
  std::vector<float> depth(n, 1.f), radius(n, 0.f), plane[3];
  for (auto& c : plane) c.resize(n, 0.f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x, j = size_t(y) * stride + x;
      depth[j] = float(finite_depth(view_depth.data[i]));
      // Halving is exact, so this is the radius of the camera's double-precision diameter
      // rounded once, whether the diameter arrives in float (a frame's parts carry it) or not.
      radius[j] = std::min(0.5f * coc_px.data[i], max_radius);
      for (int k = 0; k < 3; ++k) plane[k][j] = color.data[i * color.channels + k];
    }

  // 2. Per tile, the farthest any pixel can reach into it: the largest radius among the tiles
  //    within reach, plus the antialiased edge. In-focus regions then gather almost nothing.
  const int tiles_x = (w + kTile - 1) / kTile, tiles_y = (h + kTile - 1) / kTile;
  std::vector<float> tile_max(size_t(tiles_x) * tiles_y, 0.f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float& m = tile_max[size_t(y / kTile) * tiles_x + x / kTile];
      m = std::max(m, radius[size_t(y) * stride + x]);
    }
  const int reach_x = int(std::ceil((max_radius + 1) / kTile));
  const int reach_y = int(std::ceil((max_radius + 1) * aspect / kTile));
  std::vector<float> tile_reach(tile_max.size(), 0.f);
  for (int ty = 0; ty < tiles_y; ++ty)
    for (int tx = 0; tx < tiles_x; ++tx) {
      float m = 0;
      for (int j = std::max(0, ty - reach_y); j <= std::min(tiles_y - 1, ty + reach_y); ++j)
        for (int i = std::max(0, tx - reach_x); i <= std::min(tiles_x - 1, tx + reach_x); ++i)
          m = std::max(m, tile_max[size_t(j) * tiles_x + i]);
      tile_reach[size_t(ty) * tiles_x + tx] = std::max(m, 0.5f) + 1;
    }

  // 3. Gather, one row per task: each pixel is a pure function of the inputs. Along a row the
  //    samples go through kLanes at a time into per-lane sums (added up in a fixed order at
  //    the end), which the compiler turns into vector instructions.
  // |q − p| for every offset a gather can reach (in horizontal pixels), looked up instead of
  // computed per sample; kLanes of slack on the right for the padded lanes.
  const int max_rx = int(std::ceil(max_radius + 1.5f)),
            max_ry = int(std::ceil((max_radius + 1.5f) * aspect));
  const int distance_width = 2 * max_rx + 1 + kLanes;
  std::vector<float> distance(size_t(distance_width) * (2 * max_ry + 1));
  for (int j = -max_ry; j <= max_ry; ++j)
    for (int i = -max_rx; i < distance_width - max_rx; ++i) {
      float dx = float(i), dy = float(j) / aspect;
      distance[size_t(j + max_ry) * distance_width + (i + max_rx)] = std::sqrt(dx * dx + dy * dy);
    }
  const Gather gather{w,
                      h,
                      stride,
                      aspect,
                      float(settings.depth_tolerance),
                      tiles_x,
                      depth.data(),
                      radius.data(),
                      {plane[0].data(), plane[1].data(), plane[2].data()},
                      tile_reach.data(),
                      distance.data(),
                      distance_width,
                      max_rx,
                      max_ry,
                      out.data.data()};
  tbb::parallel_for(0, h, [&](int y) {
#if defined(__x86_64__) && defined(__GNUC__)
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (avx2) return gather_row_avx2(gather, y);
#endif
    gather_row_baseline(gather, y);
  });
  return out;
}

}  // namespace obscura::raster
