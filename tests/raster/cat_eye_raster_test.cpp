// The rasterizer's accumulated depth of field through a thin lens with a lens barrel: each lens
// point's frame is kept or dropped per pixel, so an out-of-focus point near the corner loses the
// share of its bokeh the barrel cuts off. Against the closed-form overlap of the aperture and
// the barrel's shadow (two discs; vignetting.h), and against the tracer's image of the same
// scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "camera/white_on_black.h"
#include "obscura/raster/render.h"
#include "obscura/trace/render.h"

namespace obscura {
namespace {

constexpr int kSize = 64;
constexpr double kFocusM = 0.2, kPointDepthM = 20;

// The area of the intersection of two discs of radii a and b whose centres are d apart.
double disc_overlap(double a, double b, double d) {
  if (d >= a + b) return 0;
  if (d <= std::abs(a - b)) return std::numbers::pi * std::min(a, b) * std::min(a, b);
  const double alpha = std::acos((d * d + a * a - b * b) / (2 * d * a));
  const double beta = std::acos((d * d + b * b - a * a) / (2 * d * b));
  return a * a * (alpha - std::sin(2 * alpha) / 2) + b * b * (beta - std::sin(2 * beta) / 2);
}

Camera camera_with_barrel(bool barrel) {
  Camera c;
  c.projection = Perspective::from_vertical_fov_degrees(40);
  c.film.width_px = c.film.height_px = kSize;
  c.near_m = 0.01;
  c.far_m = 100;
  c.lens.depth_of_field = true;
  c.lens.f_number = 1.4;
  c.lens.focus_distance_m = kFocusM;
  c.lens.focus_breathing = false;
  if (barrel) {
    const double aperture = c.focal_length_mm() / c.lens.f_number;
    c.lens.vignetting.barrel_diameter_mm = 1.25 * aperture;
    c.lens.vignetting.barrel_distance_mm = c.focal_length_mm();
  }
  c.validate();
  return c;
}

// A small white square at window point w, far behind the focus plane: a bokeh disc.
Scene far_point(Point2d w) {
  Scene scene = test::white_on_black("far point");
  const double half = 0.1;  // about a pixel at this depth
  Mesh m;
  m.name = "point";
  const auto x = float(w.x * kPointDepthM), y = float(w.y * kPointDepthM);
  const auto z = float(-kPointDepthM), h = float(half);
  m.positions = {{x - h, y - h, z}, {x + h, y - h, z}, {x + h, y + h, z}, {x - h, y + h, z}};
  m.indices = {0, 1, 2, 0, 2, 3};
  scene.add_mesh(m);
  return scene;
}

double total(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, 1);
  return sum;
}

Image rasterized(const Scene& scene, const Camera& camera) {
  Film film(kSize, kSize);
  raster::RenderSettings settings;
  settings.shadow_map_size = 0;
  settings.effect_samples = 1024;
  raster::render(scene, camera, settings, film);
  return film.to_image();
}

Image traced(const Scene& scene, const Camera& camera) {
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Film film(kSize, kSize);
  render(trace, camera, test::FirstHitWhite(), {.samples_per_pixel = 256, .seed = 1}, film);
  return film.to_image();
}

TEST(CatEyeRaster, TheBarrelCutsTheOffAxisBokehByTheTwoDiscOverlap) {
  const Camera open = camera_with_barrel(false), cut = camera_with_barrel(true);
  const ScreenWindow window = open.screen_window();
  const Point2d w(0.55 * window.x_max, 0.55 * window.y_max);  // towards the upper-right corner
  const Scene scene = far_point(w);
  const double bokeh_px = open.circle_of_confusion_px(kPointDepthM);
  ASSERT_GT(bokeh_px, 8);  // a disc of many pixels, well inside the frame
  ASSERT_LT(bokeh_px, 24);

  const double kept = total(rasterized(scene, cut)) / total(rasterized(scene, open));
  // The kept share of the aperture, from the rays themselves: the ray from lens point l (the
  // aperture plane) to the point P = (w·d, −d) crosses the barrel's plane, D in front, at
  // l + (w·d − l)·D/d = l·(1 − D/d) + w·D, and passes where that is within B/2 of the axis:
  // l within (B/2)/(1 − D/d) of −w·D/(1 − D/d). The aperture (radius a) overlaps that disc.
  const Vignetting& v = cut.lens.vignetting;
  const double a = 0.5 * cut.focal_length_mm() / cut.lens.f_number;
  const double shrink = 1 - v.barrel_distance_mm / (kPointDepthM * 1000);
  const double expected = disc_overlap(a, 0.5 * v.barrel_diameter_mm / shrink,
                                       std::hypot(w.x, w.y) * v.barrel_distance_mm / shrink) /
                          (std::numbers::pi * a * a);
  ASSERT_LT(expected, 0.8);  // the barrel cuts a real part of it
  ASSERT_GT(expected, 0.2);
  std::printf("bokeh %.1f px; kept share: rasterizer %.4f, two discs %.4f\n", bokeh_px, kept,
              expected);
  EXPECT_NEAR(kept, expected, 0.02);
  // The tracer keeps or stops each lens sample's ray by the same rule.
  const double traced_kept = total(traced(scene, cut)) / total(traced(scene, open));
  std::printf("tracer %.4f\n", traced_kept);
  EXPECT_NEAR(kept, traced_kept, 0.02);
}

TEST(CatEyeRaster, TheImageCentreKeepsItsLight) {
  // The centre's pixels see the whole aperture past the barrel (B > A): the very same values.
  const Scene scene = far_point({0, 0});
  const Image open = rasterized(scene, camera_with_barrel(false));
  const Image cut = rasterized(scene, camera_with_barrel(true));
  const int m = kSize / 2;
  ASSERT_GT(open.at(m, m, 1), 0);
  for (int y = m - 1; y <= m; ++y)
    for (int x = m - 1; x <= m; ++x) EXPECT_EQ(cut.at(x, y, 1), open.at(x, y, 1));
  // On the axis every ray to the point passes the barrel (B/2 > a): the whole bokeh is kept.
  EXPECT_EQ(total(cut), total(open));
}

}  // namespace
}  // namespace obscura
