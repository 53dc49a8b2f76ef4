// Calibrated cameras (issue 14, "Performance"): the lens models' inverse map (pixel → ray) in rays
// per second, and the camera's ray generation through a calibrated lens next to the pinhole.
//   inverse/<model>: LensMap::inverse on 4096 normalized image points, each the forward map of a
//     random ray inside the model's field (pinhole models: up to 40° off the axis; the fisheyes: up
//     to 95°, on a 200° lens), so every solve lands in the validity region. Models: the ideal
//     pinhole, OpenCV's pinhole with 5 coefficients (k1 k2 p1 p2 k3: a full 2-D Newton solve, as
//     any tangential term needs) and with all 14 (rational, thin prism, tilt), Kannala–Brandt
//     (1-D Newton on θ) and the equidistant fisheye (closed form).
//   generate_ray/<camera>: PreparedCamera::generate_ray at every pixel centre of a 1920×1080 film
//     (one call per pixel, lens centre, time 0): a perspective camera and calibrated cameras with
//     the same K and no distortion, the 5-coefficient OpenCV lens, and a 200° Kannala–Brandt
//     fisheye.
//   sketch/<model>: a cheaper inverse for the pinhole model written here (not the library's), on
//     the same points as inverse/…, with its largest distance from LensMap::inverse's rays.
// items_per_second is rays per second on one thread.
// Run: build/bench/calibrated_camera_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "obscura/camera/calibrated_projection.h"
#include "obscura/camera/camera.h"
#include "obscura/camera/intrinsics.h"
#include "obscura/camera/lens_distortion.h"

namespace obscura {
namespace {

constexpr double kPi = 3.14159265358979323846;

PinholeDistortion opencv5() {
  PinholeDistortion d;
  d.k1 = -0.28;
  d.k2 = 0.12;
  d.p1 = 0.006;
  d.p2 = -0.004;
  d.k3 = -0.02;
  return d;
}

PinholeDistortion opencv14() {
  PinholeDistortion d = opencv5();
  d.k4 = 0.03;
  d.k5 = 0.01;
  d.k6 = 0.002;
  d.s1 = 0.001;
  d.s2 = -0.0005;
  d.s3 = 0.0008;
  d.s4 = 0.0002;
  d.tau_x = 0.01;
  d.tau_y = -0.005;
  return d;
}

KannalaBrandt fisheye_kb() {
  return KannalaBrandt{-0.013, 0.004, -0.0012, 0.0002};
}

// Normalized image points of random rays within `max_theta` of the axis (OpenCV frame, +Z
// forward), through the lens's forward map.
std::vector<Point2d> image_points(const LensMap& map, double max_theta) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<Point2d> points;
  while (points.size() < 4096) {
    double theta = max_theta * std::sqrt(uniform(rng));
    double phi = 2 * kPi * uniform(rng);
    Vector3d ray(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    if (auto p = map.forward(ray)) points.push_back(*p);
  }
  return points;
}

void inverse(benchmark::State& state, LensModel model, double max_field_deg, double max_theta_deg) {
  LensMap map(model, max_field_deg * kPi / 180);
  std::vector<Point2d> points = image_points(map, max_theta_deg * kPi / 180);
  size_t misses = 0;
  for (auto _ : state) {
    for (Point2d p : points) {
      auto ray = map.inverse(p);
      if (!ray) ++misses;
      benchmark::DoNotOptimize(ray);
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * points.size()));
  state.counters["misses"] = static_cast<double>(misses);
}

// A sketch of a cheaper inverse for OpenCV's pinhole model without tilt, to size what the
// library's could gain (see BENCHMARKS.md, "Calibrated cameras"): the radial start solved in r
// (not in θ through tan) with the analytic derivative, then Newton's method on the full map with
// its analytic Jacobian, norms compared squared (no hypot), and the ideal pinhole in closed form.
// Not a replacement: it has no validity-region checks.
std::optional<Vector3d> sketch_inverse(const PinholeDistortion& d, Point2d target) {
  if (d == PinholeDistortion{}) return normalize(Vector3d(target.x, target.y, 1));
  auto radial = [&](double r2, double* derivative) {
    double a = 1 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
    double b = 1 + r2 * (d.k4 + r2 * (d.k5 + r2 * d.k6));
    double da = d.k1 + r2 * (2 * d.k2 + 3 * r2 * d.k3), db = d.k4 + r2 * (2 * d.k5 + 3 * r2 * d.k6);
    *derivative = (da * b - a * db) / (b * b);
    return a / b;
  };
  double rho2 = target.x * target.x + target.y * target.y, rho = std::sqrt(rho2);
  double r = rho;
  for (int i = 0; i < 20 && rho > 0; ++i) {  // r·R(r²) = ρ
    double dR, R = radial(r * r, &dR);
    double step = (r * R - rho) / (R + 2 * r * r * dR);
    r -= step;
    if (std::abs(step) <= 1e-15 * r) break;
  }
  Point2d u = rho > 0 ? Point2d(target.x * r / rho, target.y * r / rho) : target;
  for (int i = 0; i < 20; ++i) {
    double x = u.x, y = u.y, r2 = x * x + y * y, dR, R = radial(r2, &dR);
    double ex =
        x * R + 2 * d.p1 * x * y + d.p2 * (r2 + 2 * x * x) + r2 * (d.s1 + d.s2 * r2) - target.x;
    double ey =
        y * R + d.p1 * (r2 + 2 * y * y) + 2 * d.p2 * x * y + r2 * (d.s3 + d.s4 * r2) - target.y;
    if (ex * ex + ey * ey <= 1e-30 * std::max(1.0, rho2)) break;
    double a = R + 2 * x * x * dR + 2 * d.p1 * y + 6 * d.p2 * x + 2 * x * (d.s1 + 2 * d.s2 * r2);
    double b = 2 * x * y * dR + 2 * d.p1 * x + 2 * d.p2 * y + 2 * y * (d.s1 + 2 * d.s2 * r2);
    double c = 2 * x * y * dR + 2 * d.p1 * x + 2 * d.p2 * y + 2 * x * (d.s3 + 2 * d.s4 * r2);
    double e = R + 2 * y * y * dR + 6 * d.p1 * y + 2 * d.p2 * x + 2 * y * (d.s3 + 2 * d.s4 * r2);
    double det = a * e - b * c;
    Point2d step((e * ex - b * ey) / det, (a * ey - c * ex) / det);
    u = {u.x - step.x, u.y - step.y};
    if (step.x * step.x + step.y * step.y <= 1e-32 * std::max(1.0, r2)) break;
  }
  return normalize(Vector3d(u.x, u.y, 1));
}

// The sketch on the same points as inverse/…; max_error is its largest distance from
// LensMap::inverse's ray.
void sketch(benchmark::State& state, PinholeDistortion model) {
  LensMap map(model);
  std::vector<Point2d> points = image_points(map, 40 * kPi / 180);
  double max_error = 0;
  for (Point2d p : points)
    max_error = std::max(max_error, length(*sketch_inverse(model, p) - *map.inverse(p)));
  for (auto _ : state)
    for (Point2d p : points) benchmark::DoNotOptimize(sketch_inverse(model, p));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * points.size()));
  state.counters["max_error"] = max_error;
}

BENCHMARK_CAPTURE(sketch, pinhole_ideal, PinholeDistortion{});
BENCHMARK_CAPTURE(sketch, opencv_5, opencv5());

BENCHMARK_CAPTURE(inverse, pinhole_ideal, LensModel(PinholeDistortion{}), 0, 40);
BENCHMARK_CAPTURE(inverse, opencv_5, LensModel(opencv5()), 0, 40);
BENCHMARK_CAPTURE(inverse, opencv_14, LensModel(opencv14()), 0, 40);
BENCHMARK_CAPTURE(inverse, kannala_brandt, LensModel(fisheye_kb()), 100, 95);
BENCHMARK_CAPTURE(inverse, equidistant, LensModel(ClassicFisheye{}), 100, 95);

Camera perspective_camera() {
  Camera camera;
  camera.film.width_px = 1920;
  camera.film.height_px = 1080;
  Perspective p;
  p.focal_length_mm = 24;
  camera.projection = p;
  return camera;
}

// The perspective camera made calibrated: the same K, with `lens`.
Camera calibrated_camera(LensModel lens, double max_field_deg = 0) {
  Camera camera = perspective_camera();
  CalibratedProjection c;
  c.k = intrinsics(camera);
  c.lens = lens;
  c.max_field_angle_degrees = max_field_deg;
  camera.projection = c;
  return camera;
}

void generate_ray(benchmark::State& state, Camera camera) {
  camera.validate();
  PreparedCamera prepared = camera.prepare();
  const int w = camera.film.width_px, h = camera.film.height_px;
  size_t misses = 0;
  for (auto _ : state) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        auto ray = prepared.generate_ray({x + 0.5, y + 0.5});
        if (!ray) ++misses;
        benchmark::DoNotOptimize(ray);
      }
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * w * h);
  state.counters["misses"] = static_cast<double>(misses) / static_cast<double>(state.iterations());
}

BENCHMARK_CAPTURE(generate_ray, perspective, perspective_camera())->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(generate_ray, calibrated_ideal, calibrated_camera(PinholeDistortion{}))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(generate_ray, calibrated_opencv_5, calibrated_camera(opencv5()))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(generate_ray, calibrated_kannala_brandt, calibrated_camera(fisheye_kb(), 100))
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace obscura
