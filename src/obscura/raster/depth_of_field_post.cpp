#include "obscura/raster/depth_of_field_post.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "obscura/math/error.h"

namespace obscura::raster {

namespace {

constexpr int kTile = 16;  // pixels; the gather radius is chosen per tile
// Depth standing in for "nothing drawn" (+∞): far enough that its circle of confusion equals
// the formula's limit S → ∞ to 12 digits, finite so that depth differences stay numbers.
constexpr double kFarDepthM = 1e12;

double finite_depth(float d) {
  return std::isfinite(d) && d > 0 ? double(d) : kFarDepthM;
}

struct Layer {
  double weight = 0;
  double rgb[3] = {0, 0, 0};
  void add(double w, const float* c) {
    weight += w;
    for (int k = 0; k < 3; ++k) rgb[k] += w * c[k];
  }
};

}  // namespace

Image depth_of_field_post(const Image& color, const Image& view_depth, const Camera& camera,
                          const PostDepthOfFieldSettings& settings) {
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
  if (!(settings.max_coc_px >= 0) || !std::isfinite(settings.max_coc_px))
    throw Error("depth_of_field_post.max_coc_px",
                "must be finite and ≥ 0; got " + std::to_string(settings.max_coc_px));
  if (!(settings.depth_tolerance > 0))
    throw Error("depth_of_field_post.depth_tolerance",
                "must be positive; got " + std::to_string(settings.depth_tolerance));

  const int w = color.width, h = color.height;
  Image out(w, h, 3);
  out.channel_names = {"R", "G", "B"};

  // 1. Depth and blur radius per pixel. Radii are in horizontal pixels; with non-square pixels
  //    a disk is `aspect` times taller in pixel rows.
  const double aspect = camera.film.pixel_aspect;
  const double max_radius = 0.5 * settings.max_coc_px;
  std::vector<double> depth(size_t(w) * h), radius(size_t(w) * h);
  for (size_t i = 0; i < depth.size(); ++i) {
    depth[i] = finite_depth(view_depth.data[i]);
    radius[i] = std::min(0.5 * camera.circle_of_confusion_px(depth[i]), max_radius);
  }

  // 2. Per tile, the farthest any pixel can reach into it: the largest radius among the tiles
  //    within reach, plus the antialiased edge. In-focus regions then gather almost nothing.
  const int tiles_x = (w + kTile - 1) / kTile, tiles_y = (h + kTile - 1) / kTile;
  std::vector<double> tile_max(size_t(tiles_x) * tiles_y, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double& m = tile_max[size_t(y / kTile) * tiles_x + x / kTile];
      m = std::max(m, radius[size_t(y) * w + x]);
    }
  const int reach_x = int(std::ceil((max_radius + 1) / kTile));
  const int reach_y = int(std::ceil((max_radius + 1) * aspect / kTile));
  std::vector<double> tile_reach(tile_max.size(), 0.0);
  for (int ty = 0; ty < tiles_y; ++ty)
    for (int tx = 0; tx < tiles_x; ++tx) {
      double m = 0;
      for (int j = std::max(0, ty - reach_y); j <= std::min(tiles_y - 1, ty + reach_y); ++j)
        for (int i = std::max(0, tx - reach_x); i <= std::min(tiles_x - 1, tx + reach_x); ++i)
          m = std::max(m, tile_max[size_t(j) * tiles_x + i]);
      tile_reach[size_t(ty) * tiles_x + tx] = std::max(m, 0.5) + 1;
    }

  // 3. Gather, one row per task: each pixel is a pure function of the inputs.
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const size_t p = size_t(y) * w + x;
      const double z_p = depth[p], r_p = radius[p];
      const double tolerance = settings.depth_tolerance * z_p;
      const double reach = tile_reach[size_t(y / kTile) * tiles_x + x / kTile];
      const int rx = int(std::ceil(reach)), ry = int(std::ceil(reach * aspect));
      Layer front, back;  // samples in front of p; p's own layer and what lies behind it
      for (int qy = std::max(0, y - ry); qy <= std::min(h - 1, y + ry); ++qy) {
        const double dy = (qy - y) / aspect;
        for (int qx = std::max(0, x - rx); qx <= std::min(w - 1, x + rx); ++qx) {
          const double dx = qx - x;
          const double d = std::sqrt(dx * dx + dy * dy);
          if (d >= reach) continue;
          const size_t q = size_t(qy) * w + qx;
          const double z_q = depth[q];
          const double behind = std::clamp((z_q - z_p) / tolerance, 0.0, 1.0);
          const double in_front = std::clamp((z_p - z_q) / tolerance, 0.0, 1.0);
          // Behind p, a sample spreads no farther than p's own blur.
          const double r =
              std::max(radius[q] + behind * (std::min(radius[q], r_p) - radius[q]), 0.5);
          const double coverage = std::clamp(r + 0.5 - d, 0.0, 1.0);
          if (coverage == 0) continue;
          const double weight = coverage / std::max(std::numbers::pi * r * r * aspect, 1.0);
          const float* c = &color.data[q * color.channels];
          if (in_front > 0) front.add(in_front * weight, c);
          if (in_front < 1) back.add((1 - in_front) * weight, c);
        }
      }
      // p itself is always in `back` with coverage 1, so back.weight > 0.
      const double alpha = std::min(front.weight, 1.0);
      for (int k = 0; k < 3; ++k) {
        double b = back.rgb[k] / back.weight;
        double f = front.weight > 0 ? front.rgb[k] / front.weight : 0.0;
        out.data[p * 3 + k] = float(alpha * f + (1 - alpha) * b);
      }
    }
  });
  return out;
}

}  // namespace obscura::raster
