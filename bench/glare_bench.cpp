// Diffraction glare at 4K: a 3840×2160 linear RGB float film through a 50 mm f/8 lens with a
// six-bladed iris on a 36 × 24 mm sensor (pixel pitch 9.4 µm), PSF radius 256 pixels (the
// default). Measured in parts: the colour PSF (pupil FFT + 40 wavelength bands), the FFT
// convolution of the three channels, and both together (what `--glare` costs), each at 1 thread
// and at all of the machine's threads.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <thread>

#include "obscura/camera/camera.h"
#include "obscura/film/glare.h"
#include "obscura/math/rng.h"
#include "obscura/render/camera_glare.h"

namespace {

using namespace obscura;

Camera camera_4k() {
  Camera c;
  Perspective lens;
  lens.focal_length_mm = 50;
  c.projection = lens;
  c.film.width_px = 3840;
  c.film.height_px = 2160;
  c.lens.f_number = 8;
  c.lens.aperture.blades = 6;
  return c;
}

Image film_4k() {
  Image image(3840, 2160, 3);
  Pcg32 rng(1);
  for (float& v : image.data) v = rng.next_float() > 0.9999f ? 1e5f : rng.next_float();
  return image;
}

int threads_of(const benchmark::State& state) {
  return state.range(0) > 0 ? int(state.range(0)) : int(std::thread::hardware_concurrency());
}

void BM_GlarePsf4k(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads_of(state));
  const Camera camera = camera_4k();
  for (auto _ : state) benchmark::DoNotOptimize(glare_psf(camera, {}));
}

void BM_GlareConvolve4k(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads_of(state));
  const Camera camera = camera_4k();
  const Image psf = glare_psf(camera, {});
  const Image source = film_4k();
  for (auto _ : state) {
    state.PauseTiming();
    Image image = source;
    state.ResumeTiming();
    convolve_with_psf(image, psf);
    benchmark::DoNotOptimize(image.data.data());
  }
}

void BM_Glare4k(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads_of(state));
  const Camera camera = camera_4k();
  const Image source = film_4k();
  for (auto _ : state) {
    state.PauseTiming();
    Image image = source;
    state.ResumeTiming();
    apply_glare(image, camera, {});
    benchmark::DoNotOptimize(image.data.data());
  }
}

// Argument: threads (0 = all).
BENCHMARK(BM_GlarePsf4k)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GlareConvolve4k)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Glare4k)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
