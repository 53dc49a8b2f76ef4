// The rasterizer draws a lens-system camera through its fitted camera with its measured
// vignetting: white squares on black land where the tracer, tracing the double-Gauss surface by
// surface, puts them (centroids within a fraction of a pixel), and a uniform white wall falls
// off from the centre to the corners as the tracer's does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "camera/white_on_black.h"
#include "obscura/camera/builtin_lenses.h"
#include "obscura/raster/render.h"
#include "obscura/trace/render.h"

namespace obscura {
namespace {

Camera double_gauss(int width, int height, double focus_m) {
  Camera c;
  LensSystemProjection p;
  p.lens = builtin_lens("double-gauss-50mm");
  p.sensor_width_mm = 36;
  c.projection = p;
  c.film.width_px = width;
  c.film.height_px = height;
  c.lens.focus_distance_m = focus_m;
  c.near_m = 0.01;
  c.far_m = 100;
  c.validate();
  return c;
}

void add_square(Scene& scene, Point3d centre, double half) {
  Mesh m;
  m.name = "square";
  const auto x0 = float(centre.x - half), x1 = float(centre.x + half);
  const auto y0 = float(centre.y - half), y1 = float(centre.y + half), z = float(centre.z);
  m.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  m.indices = {0, 1, 2, 0, 2, 3};
  scene.add_mesh(m);
}

Image traced(const Scene& scene, const Camera& camera, int spp) {
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Film film(camera.film.width_px, camera.film.height_px);
  render(trace, camera, test::FirstHitWhite(), {.samples_per_pixel = spp, .seed = 1}, film);
  return film.to_image();
}

Image rasterized(const Scene& scene, const Camera& camera, raster::RenderStats* stats = nullptr) {
  Film film(camera.film.width_px, camera.film.height_px);
  raster::RenderSettings settings;
  settings.msaa_samples = 8;
  raster::RenderStats s = raster::render(scene, camera, settings, film);
  if (stats) *stats = s;
  return film.to_image();
}

// The intensity-weighted centroid of the green channel in a window around `guess`.
Point2d centroid(const Image& image, Point2d guess, int half) {
  double sx = 0, sy = 0, sum = 0;
  for (int y = int(guess.y) - half; y <= int(guess.y) + half; ++y)
    for (int x = int(guess.x) - half; x <= int(guess.x) + half; ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      double v = image.at(x, y, 1);
      sx += v * (x + 0.5), sy += v * (y + 0.5), sum += v;
    }
  return {sx / sum, sy / sum};
}

TEST(LensSystemRaster, SquaresLandWhereTheTracerPutsThem) {
  constexpr double kFocusM = 3;
  const Camera camera = double_gauss(192, 128, kFocusM);
  Scene scene = test::white_on_black("squares");
  // A grid over the frame on the plane of focus (the frame is about 2.1 x 1.4 m there) and three
  // nearer squares around the centre (their blur is symmetric there).
  std::vector<Point3d> centres;
  for (int j = -2; j <= 2; ++j)
    for (int i = -3; i <= 3; ++i) centres.push_back({0.3 * i, 0.25 * j, -kFocusM});
  for (int i = -1; i <= 1; ++i) centres.push_back({0.08 * i, 0.1, -1.5});
  for (const Point3d& c : centres) add_square(scene, c, c.z == -kFocusM ? 0.04 : 0.02);
  raster::RenderStats stats;
  const Image drawn = rasterized(scene, camera, &stats), path = traced(scene, camera, 64);
  ASSERT_FALSE(stats.warnings.empty());
  EXPECT_NE(stats.warnings.back().find("fitted"), std::string::npos) << stats.warnings.back();
  double worst = 0;
  for (const Point3d& c : centres) {
    auto at = camera.project(c);
    ASSERT_TRUE(at);
    Point2d a = centroid(drawn, at->film_point, 5), b = centroid(path, at->film_point, 5);
    worst = std::max(worst, std::hypot(a.x - b.x, a.y - b.y));
  }
  std::printf("worst square centroid, rasterizer vs tracer: %.3f px\n", worst);
  EXPECT_LT(worst, 0.3);
}

TEST(LensSystemRaster, WallDarkensTowardsTheCornersAsInTheTracer) {
  const Camera camera = double_gauss(48, 32, 3);
  Scene scene = test::white_on_black("wall");
  add_square(scene, {0, 0, -3}, 3);
  const Image drawn = rasterized(scene, camera), path = traced(scene, camera, 256);
  // 6 x 6 pixel patches: the centre and the four corners.
  auto patch = [](const Image& image, int x0, int y0) {
    double sum = 0;
    for (int y = y0; y < y0 + 6; ++y)
      for (int x = x0; x < x0 + 6; ++x) sum += image.at(x, y, 1);
    return sum / 36;
  };
  const double drawn_centre = patch(drawn, 21, 13), path_centre = patch(path, 21, 13);
  EXPECT_NEAR(drawn_centre, path_centre, 0.02 * path_centre);
  for (auto [x, y] : {std::pair{0, 0}, std::pair{42, 0}, std::pair{0, 26}, std::pair{42, 26}}) {
    const double drawn_ratio = patch(drawn, x, y) / drawn_centre;
    const double path_ratio = patch(path, x, y) / path_centre;
    EXPECT_LT(path_ratio, 0.6);  // the double-Gauss wide open loses half its light there
    EXPECT_NEAR(drawn_ratio, path_ratio, 0.03 * path_ratio) << x << ", " << y;
    std::printf("corner (%d, %d) / centre: rasterizer %.4f, tracer %.4f\n", x, y, drawn_ratio,
                path_ratio);
  }
}

}  // namespace
}  // namespace obscura
