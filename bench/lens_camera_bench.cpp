// Lens-system cameras (issue 15, "Performance"): camera rays per second through a real lens
// (exit-pupil sampling, every surface traced) next to the thin-lens camera's, on one thread.
//   generate_ray/thin_lens: a perspective camera with depth of field (50 mm f/2 on 36 × 24 mm).
//   generate_ray/<lens>: the built-in lens systems on the same sensor, focused at 3 m.
// Each iteration is PreparedCamera::generate_ray at every pixel centre of a 640 × 426 film with
// a Halton-like lens sample; rays the lens stops count too (they are what a render asks for).
// The counter `passed` is the share of lens-system rays the lens lets through.
// Run: build/bench/lens_camera_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "obscura/camera/builtin_lenses.h"
#include "obscura/camera/camera.h"

namespace obscura {
namespace {

constexpr int kWidth = 640, kHeight = 426;

Camera base_camera() {
  Camera c;
  c.film.width_px = kWidth;
  c.film.height_px = kHeight;
  c.lens.focus_distance_m = 3;
  return c;
}

// The radical inverse in base b: a low-discrepancy lens sample per pixel.
double radical_inverse(int i, int b) {
  double f = 1, r = 0;
  for (; i > 0; i /= b) r += (f /= b) * (i % b);
  return r;
}

void run(benchmark::State& state, const Camera& camera) {
  camera.validate();
  const PreparedCamera prepared = camera.prepare(true);
  long rays = 0, passed = 0;
  for (auto _ : state) {
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        int i = y * kWidth + x;
        auto r = prepared.generate_ray({x + 0.5, y + 0.5},
                                       {radical_inverse(i, 2), radical_inverse(i, 3)});
        passed += r.has_value();
        benchmark::DoNotOptimize(r);
      }
    rays += kWidth * kHeight;
  }
  state.SetItemsProcessed(rays);
  state.counters["passed"] = double(passed) / double(rays);
}

void thin_lens(benchmark::State& state) {
  Camera c = base_camera();
  c.projection = Perspective{};
  c.lens.depth_of_field = true;
  c.lens.f_number = 2;
  run(state, c);
}
BENCHMARK(thin_lens)->Name("generate_ray/thin_lens")->Unit(benchmark::kMillisecond);

void lens_system(benchmark::State& state, const std::string& name) {
  Camera c = base_camera();
  LensSystemProjection p;
  p.lens = builtin_lens(name);
  c.projection = p;
  run(state, c);
}
BENCHMARK_CAPTURE(lens_system, double_gauss, std::string("double-gauss-50mm"))
    ->Name("generate_ray/double-gauss-50mm")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lens_system, telephoto, std::string("telephoto-250mm"))
    ->Name("generate_ray/telephoto-250mm")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lens_system, fisheye, std::string("fisheye-10mm"))
    ->Name("generate_ray/fisheye-10mm")
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace obscura
