// Depth of field and motion blur as the tracer renders them: the camera's thin lens and shutter
// are sampled like any other dimension. Edges are measured on the image and compared with the
// blur the optics predict.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "obscura/camera/frames.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

std::shared_ptr<EmbreeDevice> device() {
  return testing::embree_device();
}

constexpr int kWidth = 96, kHeight = 8;

// An emitting half-plane x ≥ 0 at depth `depth` in front of a camera at the origin looking down
// −Z; everything else black. The image is a vertical edge through the centre column.
TraceScene edge_scene(double depth) {
  Scene scene;
  scene.name = "edge";
  scene.materials = {diffuse_material("white", Rgb(0.f), Rgb(1.f))};
  auto z = float(-depth);
  Mesh plane;
  plane.name = "half-plane";
  plane.positions = {{0, -50, z}, {50, -50, z}, {50, 50, z}, {0, 50, z}};
  plane.indices = {0, 1, 2, 0, 2, 3};
  scene.add_mesh(std::move(plane));
  return TraceScene(scene, device());
}

Camera camera_50mm() {
  Camera camera;
  Perspective lens;
  lens.focal_length_mm = 50;
  lens.sensor_width_mm = 36;
  lens.sensor_height_mm = 36.0 * kHeight / kWidth;
  camera.projection = lens;
  camera.film.width_px = kWidth;
  camera.film.height_px = kHeight;
  return camera;
}

// The edge's profile: each column's mean over the rows.
std::vector<double> profile(const TraceScene& scene, const Camera& camera, int spp) {
  Film film(kWidth, kHeight);
  render(scene, camera, PathTracer(), {.samples_per_pixel = spp, .seed = 5}, film);
  std::vector<double> p(kWidth, 0.0);
  for (int x = 0; x < kWidth; ++x)
    for (int y = 0; y < kHeight; ++y) p[x] += film.pixel({x, y}).g / kHeight;
  return p;
}

// Where a rising profile (one value per pixel centre, x + 0.5) crosses `level`.
double crossing(const std::vector<double>& p, double level) {
  for (size_t x = 1; x < p.size(); ++x)
    if (p[x - 1] < level && p[x] >= level) return x - 0.5 + (level - p[x - 1]) / (p[x] - p[x - 1]);
  return -1;
}

double width_10_90(const std::vector<double>& p) {
  return crossing(p, 0.9) - crossing(p, 0.1);
}

// The same width for an edge blurred by `kernel_edge` (the fraction of the blur kernel left of
// offset s, in pixels), then box-filtered over a pixel and point-sampled at pixel centres —
// computed by brute force, independently of the renderer.
double predicted_width_10_90(const std::function<double(double)>& kernel_edge) {
  std::vector<double> p(kWidth);
  for (int x = 0; x < kWidth; ++x) {
    double sum = 0;
    const int n = 200;
    for (int i = 0; i < n; ++i) sum += kernel_edge(x + (i + 0.5) / n - kWidth / 2.0);
    p[x] = sum / n;
  }
  return width_10_90(p);
}

TEST(DepthOfField, InFocusStaysSharpAndTwiceTheDistanceBlursByTheCircleOfConfusion) {
  Camera camera = camera_50mm();
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 1;
  camera.lens.focus_distance_m = 0.5;
  double focused = width_10_90(profile(edge_scene(0.5), camera, 64));
  EXPECT_LE(focused, 1.0);

  std::vector<double> far = profile(edge_scene(1), camera, 256);
  double coc_px = camera.circle_of_confusion_px(1);
  ASSERT_GT(coc_px, 4);  // a clearly visible blur
  // A uniform disk of radius R: the part left of a chord at offset s.
  double r = coc_px / 2;
  auto disk_edge = [r](double s) {
    if (s <= -r) return 0.0;
    if (s >= r) return 1.0;
    double area = r * r * std::acos(-s / r) + s * std::sqrt(r * r - s * s);
    return area / (std::numbers::pi * r * r);
  };
  EXPECT_NEAR(width_10_90(far), predicted_width_10_90(disk_edge), 0.35)
      << "circle of confusion " << coc_px << " px";
}

TEST(MotionBlur, AnEdgeBlursByItsTravelDuringTheShutter) {
  // The camera slides 10 cm along +X while the shutter is open: an edge 2 m away moves across
  // the film by f·T/S, as a uniform smear.
  Camera camera = camera_50mm();
  camera.shutter = {.open_s = 0, .close_s = 0.01};
  camera.world_from_camera =
      AnimatedTransform({{0.0, Transform()}, {0.01, Transform::translate({0.1, 0, 0})}});
  double pixel_mm = 36.0 / kWidth;
  double travel_px = 50 * 0.1 / 2 / pixel_mm;  // f·T/S on the sensor, in pixels
  ASSERT_GT(travel_px, 5);
  auto smear_edge = [travel_px](double s) { return std::clamp(s / travel_px + 0.5, 0.0, 1.0); };
  double measured = width_10_90(profile(edge_scene(2), camera, 256));
  EXPECT_NEAR(measured, predicted_width_10_90(smear_edge), 0.35) << "travel " << travel_px;

  camera.shutter = {.open_s = 0, .close_s = 0};  // instantaneous: sharp again
  EXPECT_LE(width_10_90(profile(edge_scene(2), camera, 16)), 1.0);
}

}  // namespace
}  // namespace obscura
