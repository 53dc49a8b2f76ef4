// Shared by the camera-effects tests: a 50 mm camera at the origin looking down −Z onto a thin
// strip of film, world-space quads drawn through raster::draw, and edge profiles measured the
// way the tracer's depth-of-field tests measure them.
#pragma once

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/raster/accumulation.h"
#include "obscura/raster/pipeline.h"
#include "obscura/raster/shaders.h"

namespace obscura::raster::test {

constexpr int kStripWidth = 96, kStripHeight = 8;
constexpr double kPixelMm = 36.0 / kStripWidth;  // a 36 mm sensor across 96 pixels

inline Camera strip_camera(int height_px = kStripHeight) {
  Camera camera;
  Perspective lens;
  lens.focal_length_mm = 50;
  lens.sensor_width_mm = 36;
  lens.sensor_height_mm = kPixelMm * height_px;
  camera.projection = lens;
  camera.film.width_px = kStripWidth;
  camera.film.height_px = height_px;
  return camera;
}

// An axis-aligned rectangle [x0, x1] × [y0, y1] facing the camera at depth `depth` (z = −depth).
struct Rect {
  double x0, x1, y0, y1, depth;
  Rgb color{1, 1, 1};
};

// Draws the rectangles (in order, depth-tested) with the frame's matrices.
inline void draw_rects(const std::vector<Rect>& rects, const FrameParameters& frame,
                       RenderTarget& target) {
  std::vector<MeshVertex> vertices;
  for (const Rect& r : rects) {
    auto z = float(-r.depth);
    auto corner = [&](double x, double y) {
      return MeshVertex{{float(x), float(y), z}, {0, 0, 1}, {0, 0}, r.color, 1.f, {}, {}};
    };
    MeshVertex a = corner(r.x0, r.y0), b = corner(r.x1, r.y0), c = corner(r.x1, r.y1),
               d = corner(r.x0, r.y1);
    for (const MeshVertex& v : {a, b, c, a, c, d}) vertices.push_back(v);
  }
  UnlitProgram program;
  program.scene.clip_from_world = Matrix4f(frame.clip_from_world());
  draw_with_depth_func<DepthFunc::kLess>(target, DrawState{}, program, vertices);
}

// The green channel of row `row`.
inline std::vector<double> row_profile(const Image& image, int row) {
  std::vector<double> p(size_t(image.width));
  for (int x = 0; x < image.width; ++x) p[size_t(x)] = image.at(x, row, 1);
  return p;
}

// Where a rising profile (one value per pixel centre, x + 0.5) first crosses `level`.
inline double crossing(const std::vector<double>& p, double level) {
  for (size_t x = 1; x < p.size(); ++x)
    if (p[x - 1] < level && p[x] >= level) return x - 0.5 + (level - p[x - 1]) / (p[x] - p[x - 1]);
  return -1;
}

inline double width_10_90(const std::vector<double>& p) {
  return crossing(p, 0.9) - crossing(p, 0.1);
}

// The 10–90 % width of an edge at raster x = `edge_x` blurred by a kernel whose mass left of
// offset s is kernel_edge(s), point-sampled at pixel centres (the rasterizer samples each pixel
// at its centre; no pixel filter).
inline double predicted_width_10_90(const std::function<double(double)>& kernel_edge,
                                    double edge_x = kStripWidth / 2.0) {
  std::vector<double> p(kStripWidth);
  for (int x = 0; x < kStripWidth; ++x) p[size_t(x)] = kernel_edge(x + 0.5 - edge_x);
  return width_10_90(p);
}

// A uniform disk of radius r: the part of its area left of the chord at offset s.
inline double disk_edge(double r, double s) {
  if (s <= -r) return 0.0;
  if (s >= r) return 1.0;
  double area = r * r * std::acos(-s / r) + s * std::sqrt(r * r - s * s);
  return area / (std::numbers::pi * r * r);
}

// How many pixels are strictly between the two sides of an edge.
inline int partial_pixels(const std::vector<double>& p, double low, double high) {
  int n = 0;
  for (double v : p) n += v > low + 1e-6 && v < high - 1e-6;
  return n;
}

}  // namespace obscura::raster::test
