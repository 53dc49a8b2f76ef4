// A rolling shutter against the kinematics it models: a camera panning past a vertical bar at a
// known speed, read out line by line, sees the bar lean by (image speed × line time) per line.
// The tracer must put the bar there on every line; the rasterizer, drawing bands of lines, within
// its stated bound; the ground truth's time channel and flow must follow the lines' times.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "obscura/camera/intrinsics.h"
#include "obscura/raster/rolling_shutter.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/scene/ground_truth.h"
#include "obscura/scene/scene.h"
#include "obscura/scene/surface_motion.h"
#include "obscura/trace/ground_truth_render.h"
#include "obscura/trace/render.h"
#include "white_on_black.h"

namespace obscura {
namespace {

constexpr int kSize = 96;
constexpr double kDistance = 5;            // camera to bar, metres
constexpr double kSpeed = 2;               // camera's sideways speed, m/s
constexpr double kLineTime = 0.5 / kSize;  // the readout takes half a second
constexpr double kBarHalfWidth = 0.05;     // metres

// An emitting vertical bar at x = 0 in the plane z = 0, tall enough to cross every line.
Scene bar_scene() {
  Scene scene = test::white_on_black("bar");
  Mesh bar;
  bar.name = "bar";
  const float w = float(kBarHalfWidth);
  bar.positions = {{-w, -10, 0}, {w, -10, 0}, {w, 10, 0}, {-w, 10, 0}};
  bar.indices = {0, 1, 2, 0, 2, 3};
  scene.add_mesh(bar);
  // The camera pans from x = −1 m at t = 0 to x = +1 m at t = 1 s, looking down −Z at the bar,
  // with an instantaneous exposure per line read top to bottom.
  Camera& c = scene.camera;
  c.projection = Perspective::from_vertical_fov_degrees(40);
  c.film.width_px = kSize;
  c.film.height_px = kSize;
  c.world_from_camera = AnimatedTransform({{0, Transform::translate({-1, 0, kDistance})},
                                           {1, Transform::translate({1, 0, kDistance})}});
  c.shutter = {.open_s = 0, .close_s = 0, .line_time_s = kLineTime};
  c.validate();
  return scene;
}

// Where the bar's centre is on line j: the camera at x(t) = −1 + 2t sees x = 0 at
// cx + fx · (0 − x(t)) / D, with t the line's time j · line time.
double expected_bar_x(const Camera& camera, int line) {
  const double t = line * kLineTime;
  const double camera_x = -1 + kSpeed * t;
  return intrinsics(camera).cx + 0.5 + intrinsics(camera).fx * (0 - camera_x) / kDistance;
}

// The bar's centre on line j from the pixels' coverage (box-filtered: a pixel's value is the
// fraction of it the bar covers): the left edge is where the first lit pixel's coverage begins,
// the width is the total coverage.
double measured_bar_x(const Image& image, int line) {
  double width = 0;
  int first = -1;
  for (int x = 0; x < image.width; ++x) {
    double c = image.at(x, line, 1);
    width += c;
    if (first < 0 && c > 1e-6) first = x;
  }
  if (first < 0) return -1;
  double left = first + 1 - image.at(first, line, 1);
  return left + width / 2;
}

TEST(RollingShutter, TracerLeansTheBarByImageSpeedTimesLineTimeOnEveryLine) {
  Scene scene = bar_scene();
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Film film(kSize, kSize);
  render(trace, scene.camera, test::FirstHitWhite(), {.samples_per_pixel = 256, .seed = 3}, film);
  Image image = film.to_image();
  // The lean: fx · v / D px per second, over a 0.5 s readout: about 26 px from top to bottom.
  double lean = measured_bar_x(image, 0) - measured_bar_x(image, kSize - 1);
  EXPECT_NEAR(lean, intrinsics(scene.camera).fx * kSpeed / kDistance * (kSize - 1) * kLineTime,
              0.05);
  for (int line = 0; line < kSize; ++line)
    EXPECT_NEAR(measured_bar_x(image, line), expected_bar_x(scene.camera, line), 0.03) << line;
}

TEST(RollingShutter, RasterizerBandsStayWithinTheirStatedBound) {
  Scene scene = bar_scene();
  raster::RasterSettings settings;
  settings.msaa_samples = 8;
  settings.surface_lights = false;
  raster::SceneRasterizer rasterizer(scene, settings);
  for (int bands : {8, 32}) {
    Film film(kSize, kSize);
    raster::draw_rolling_shutter(
        scene.camera, bands,
        [&](const Camera& c, Film& f) {
          rasterizer.render(c, f);
          return std::vector<Image>{};
        },
        film);
    Image image = film.to_image();
    // A line is drawn at its band's middle time: off by ≤ (lines per band − 1)/2 line times.
    const double image_speed = intrinsics(scene.camera).fx * kSpeed / kDistance;  // px/s
    const double lines_per_band = std::ceil(double(kSize) / bands);
    const double bound = image_speed * (lines_per_band - 1) / 2 * kLineTime;
    double worst = 0;
    for (int line = 0; line < kSize; ++line)
      worst = std::max(worst,
                       std::abs(measured_bar_x(image, line) - expected_bar_x(scene.camera, line)));
    EXPECT_LE(worst, bound + 0.06) << bands << " bands";  // + the edge's anti-aliasing
    EXPECT_GE(worst, 0.5 * bound) << "the bound is tight, not vacuous";
  }
}

TEST(RollingShutter, GroundTruthTimesAndFlowFollowTheLines) {
  Scene scene = bar_scene();
  Camera& c = scene.camera;
  c.shutter.close_s = 0.25;  // flow between the exposures' starts 0 and 0.25 s
  TraceSceneOptions options;
  options.shutter = Shutter{.open_s = 0, .close_s = 1};
  TraceScene trace(scene, std::make_shared<EmbreeDevice>(), options);
  GroundTruthBuffer gt = render_ground_truth(trace, SurfaceMotion(scene), c, {0, 0.25});
  int checked = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      // Line y starts exposing y line times after the shutter opens.
      ASSERT_EQ(gt.value(x, y, "time"), float(y * kLineTime));  // stored as float
      float fx = gt.value(x, y, "flow.forward.X"), fy = gt.value(x, y, "flow.forward.Y");
      if (std::isnan(fx)) continue;
      // The static point P seen here lands at q = p + flow in the second exposure, on a line
      // that is exposed at 0.25 s + its own delay: q must be P's image at exactly that time.
      Point3d p(gt.value(x, y, "P.X"), gt.value(x, y, "P.Y"), gt.value(x, y, "P.Z"));
      Point2d q(x + 0.5 + fx, y + 0.5 + fy);
      double t = 0.25 + (q.y - 0.5) * kLineTime;
      auto at = c.project(p, t);
      ASSERT_TRUE(at);
      EXPECT_NEAR(at->film_point.x, q.x, 0.01);
      EXPECT_NEAR(at->film_point.y, q.y, 0.01);
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace obscura
