// Object motion blur: instances with motion keys move during the shutter (Embree time steps),
// and the blur measured on the image matches the travel computed by hand from the scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <tbb/global_control.h>

#include "obscura/math/error.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

std::shared_ptr<EmbreeDevice> device() {
  return testing::embree_device();
}

constexpr int kWidth = 96, kHeight = 8;

// A pinhole 50 mm lens on a 36 mm wide sensor at the origin, looking down −Z; shutter 10 ms.
// One pixel is 36/96 = 0.375 mm on the sensor, i.e. 0.375 mm · 2 m / 50 mm = 15 mm at 2 m.
Camera camera_50mm() {
  Camera camera;
  Perspective lens;
  lens.focal_length_mm = 50;
  lens.sensor_width_mm = 36;
  lens.sensor_height_mm = 36.0 * kHeight / kWidth;
  camera.projection = lens;
  camera.film.width_px = kWidth;
  camera.film.height_px = kHeight;
  camera.shutter = {.open_s = 0, .close_s = 0.01};
  return camera;
}

// An emitting square of side 0.4 m, 2 m in front of the camera, centred at x = 0 at rest, moved
// by `motion` (keys of its translation along +X); the square covers every row of the film.
Scene moving_square(const std::vector<std::pair<double, double>>& motion) {
  Scene scene;
  scene.name = "moving square";
  scene.materials = {diffuse_material("lamp", Rgb(0.f), Rgb(1.f))};
  Mesh square;
  square.name = "square";
  square.positions = {{-0.2f, -0.2f, -2}, {0.2f, -0.2f, -2}, {0.2f, 0.2f, -2}, {-0.2f, 0.2f, -2}};
  square.indices = {0, 1, 2, 0, 2, 3};
  scene.add_mesh(std::move(square));
  for (auto [time, x] : motion)
    scene.instances[0].motion.push_back({time, Transform::translate({x, 0, 0})});
  scene.camera = camera_50mm();
  return scene;
}

std::vector<double> profile(const Scene& scene, int spp) {
  TraceScene trace(scene, device());
  Film film(kWidth, kHeight);
  render(trace, scene.camera, PathTracer(), {.samples_per_pixel = spp, .seed = 2}, film);
  std::vector<double> p(kWidth, 0.0);
  for (int x = 0; x < kWidth; ++x)
    for (int y = 0; y < kHeight; ++y) p[x] += film.pixel({x, y}).g / kHeight;
  return p;
}

// Where the profile (values at pixel centres x + 0.5) crosses `level` between columns
// [from, to), rising or falling.
double crossing(const std::vector<double>& p, double level, int from, int to) {
  for (int x = from + 1; x < to; ++x)
    if ((p[x - 1] - level) * (p[x] - level) <= 0 && p[x - 1] != p[x])
      return x - 0.5 + (level - p[x - 1]) / (p[x] - p[x - 1]);
  return -1;
}

// The 10–90 % width of a rising edge whose mid-shutter position is `edge_px`, smeared uniformly
// over `travel_px` (0: sharp), box-filtered over a pixel and point-sampled at pixel centres: by
// brute force, independently of the renderer. (The width depends on the edge's sub-pixel phase.)
double predicted_width(double edge_px, double travel_px) {
  std::vector<double> p(kWidth);
  for (int x = 0; x < kWidth; ++x) {
    double sum = 0;
    const int n = 400;
    for (int i = 0; i < n; ++i) {
      double s = x + (i + 0.5) / n - edge_px;
      sum += travel_px > 0 ? std::clamp(s / travel_px + 0.5, 0.0, 1.0) : s >= 0;
    }
    p[x] = sum / n;
  }
  return crossing(p, 0.9, 0, kWidth) - crossing(p, 0.1, 0, kWidth);
}

TEST(ObjectMotion, AMovingSquaresEdgesBlurByItsTravel) {
  // 0.1 m along +X in the 10 ms shutter, at 2 m: 0.1 · 50 / 2 = 2.5 mm on the sensor = 6.67 px.
  const double travel_px = 0.1 * 50 / 2 / 0.375;
  std::vector<double> p = profile(moving_square({{0, 0}, {0.01, 0.1}}), 256);
  // Left edge (rising) near column 48 − 13.3 + 3.3 = 38, right edge (falling) near 64.7.
  // Mid-shutter, the edges are at x = −0.15 m and 0.25 m: 48 + x · (50/2 mm) / (0.375 mm/px).
  const double left_px = 48 - 0.15 * 25 / 0.375, right_px = 48 + 0.25 * 25 / 0.375;
  double left = crossing(p, 0.9, 20, 48) - crossing(p, 0.1, 20, 48);
  double right = crossing(p, 0.1, 48, 90) - crossing(p, 0.9, 48, 90);
  EXPECT_NEAR(left, predicted_width(left_px, travel_px), 0.35);
  // The falling edge mirrored: a rising edge at 96 − right_px.
  EXPECT_NEAR(right, predicted_width(kWidth - right_px, travel_px), 0.35);
  // Half coverage where the edges are at mid-shutter.
  EXPECT_NEAR(crossing(p, 0.5, 20, 48), left_px, 0.25);
  EXPECT_NEAR(crossing(p, 0.5, 48, 90), right_px, 0.25);

  // The same keys with an instantaneous shutter at t = 0: a sharp square at rest.
  Scene still = moving_square({{0, 0}, {0.01, 0.1}});
  still.camera.shutter = {.open_s = 0, .close_s = 0};
  std::vector<double> q = profile(still, 16);
  const double rest_px = 48 - 0.2 * 25 / 0.375;
  EXPECT_NEAR(crossing(q, 0.9, 20, 48) - crossing(q, 0.1, 20, 48), predicted_width(rest_px, 0),
              0.35);
  EXPECT_NEAR(crossing(q, 0.5, 20, 48), rest_px, 0.25);
}

TEST(ObjectMotion, KeysInsideTheShutterAreFollowed) {
  // The square travels 0.1 m in the first half of the shutter and stands still in the second:
  // its time-averaged left edge is at −0.2 + (½·0.05 + ½·0.1) = −0.125 m, not at the −0.15 m a
  // straight line from the first key to the last would give. Coverage summed over the rising
  // edge's columns measures that mean position: Σ (1 − p) = edge position − start column.
  std::vector<double> p = profile(moving_square({{0, 0}, {0.005, 0.1}, {0.01, 0.1}}), 128);
  double uncovered = 0;
  for (int x = 20; x < 48; ++x) uncovered += 1 - p[x];
  EXPECT_NEAR(20 + uncovered, 48 - 0.125 * 25 / 0.375, 0.2);
}

TEST(ObjectMotion, BitIdenticalAcrossThreadCounts) {
  // A panel behind the camera lights a wall on which the moving, spinning square casts its
  // shadow: paths with bounces, shadow rays and light samples, all at their sample's time.
  Scene scene = moving_square({{0, 0}, {0.01, 0.1}});
  scene.materials.push_back(diffuse_material("wall", Rgb(0.7f)));
  Mesh wall;
  wall.name = "wall";
  wall.positions = {{-3, -3, -3}, {3, -3, -3}, {3, 3, -3}, {-3, 3, -3}};
  wall.indices = {0, 1, 2, 0, 2, 3};
  wall.material = 1;
  scene.add_mesh(wall);
  wall.name = "panel";  // facing −Z, at z = 0.5 behind the camera
  wall.positions = {{-3, -3, 0.5f}, {-3, 3, 0.5f}, {3, 3, 0.5f}, {3, -3, 0.5f}};
  wall.material = 0;
  scene.add_mesh(wall);
  scene.instances[0].motion.insert(
      scene.instances[0].motion.begin() + 1,
      {0.005, Transform::translate({0.05, 0, 0}) * Transform::rotate_z(0.5)});
  auto render_with = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    TraceScene trace(scene, device());
    Film film(kWidth, kHeight);
    render(trace, scene.camera, PathTracer(), {.samples_per_pixel = 8, .seed = 4}, film);
    return film.to_image().data;
  };
  EXPECT_EQ(render_with(1), render_with(2));
}

TEST(ObjectMotion, RenderRefusesACameraWithAnotherShutter) {
  Scene scene = moving_square({{0, 0}, {0.01, 0.1}});
  TraceScene trace(scene, device());
  EXPECT_TRUE(trace.has_motion());
  Camera other = scene.camera;
  other.shutter = {.open_s = 0, .close_s = 0.02};
  Film film(kWidth, kHeight);
  EXPECT_THROW(render(trace, other, PathTracer(), {.samples_per_pixel = 1}, film), Error);
}

}  // namespace
}  // namespace obscura
