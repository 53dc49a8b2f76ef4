// Colour pipeline throughput: a 3840×2160 linear Rec.709 float image → Display P3-encoded 8-bit
// (P3 primaries, D65, IEC 61966-2-1 sRGB curve), the conversion OpenColorIO's peer benchmark
// (shared/tools/peers/ocio) measures. Same input generator, same packed layout, separate output
// buffer, threads started inside the timed region, each taking a band of rows.
//
// Before timing, every output channel is checked against a double-precision reference (matrix
// derived from the primaries, IEC curve, round half up): the counters report the mismatches
// (expected only where the exact value lies within float rounding of a code boundary).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <thread>
#include <vector>

#include "obscura/color/color_space.h"
#include "obscura/color/convert_pixels.h"
#include "obscura/color/develop.h"

namespace {

constexpr long kWidth = 3840, kHeight = 2160;

uint64_t mix64(uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// The peer benchmark's content: 15/16 of values 4u² (0..4, dense near 0), 1/16 −0.25u.
const std::vector<float>& input() {
  static const std::vector<float> image = [] {
    std::vector<float> v(size_t(kWidth) * kHeight * 3);
    for (size_t i = 0; i < v.size(); ++i) {
      uint64_t h = mix64(i);
      double u = double(h >> 40) * (1.0 / 16777216.0);
      v[i] = (h & 15) == 0 ? float(-0.25 * u) : float(4.0 * u * u);
    }
    return v;
  }();
  return image;
}

void encode_image(const obscura::DisplayEncoder& encoder, const float* src, uint8_t* dst,
                  int threads) {
  auto band = [&](int t) {
    long y0 = kHeight * t / threads, y1 = kHeight * (t + 1) / threads;
    obscura::DevelopStats stats;
    for (long y = y0; y < y1; ++y)
      encoder.encode_rgb_row(src + size_t(y) * kWidth * 3, kWidth, 0, int(y),
                             dst + size_t(y) * kWidth * 3, stats);
    benchmark::DoNotOptimize(stats);
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(band, t);
  band(0);
  for (std::thread& w : workers) w.join();
}

struct Check {
  size_t mismatches = 0;
  int max_code_error = 0;
};

Check check_against_reference(const std::vector<uint8_t>& out) {
  using namespace obscura;
  Matrix3d m = rgb_to_rgb_matrix(primaries::kRec709, primaries::kDisplayP3);
  const std::vector<float>& in = input();
  Check c;
  for (size_t p = 0; p < out.size() / 3; ++p)
    for (int k = 0; k < 3; ++k) {
      double lin = m.m[k][0] * in[3 * p] + m.m[k][1] * in[3 * p + 1] + m.m[k][2] * in[3 * p + 2];
      double e = encode(TransferFunction::kSrgb, lin);
      int ref = int(std::floor(std::clamp(e, 0.0, 1.0) * 255 + 0.5));
      int d = std::abs(int(out[3 * p + k]) - ref);
      c.mismatches += d != 0;
      c.max_code_error = std::max(c.max_code_error, d);
    }
  return c;
}

void run(benchmark::State& state, obscura::Dither dither) {
  int threads = int(state.range(0));
  obscura::DisplaySettings settings;
  settings.display = obscura::DisplaySpace::kDisplayP3;
  settings.tonemap.op = obscura::ToneMap::kNone;
  settings.dither = dither;
  obscura::DisplayEncoder encoder(settings);
  const std::vector<float>& src = input();
  std::vector<uint8_t> dst(src.size());
  encode_image(encoder, src.data(), dst.data(), threads);  // warm-up, and the output to check
  if (dither == obscura::Dither::kNone) {
    Check c = check_against_reference(dst);
    state.counters["mismatches"] = double(c.mismatches);
    state.counters["max_code_err"] = c.max_code_error;
  }
  for (auto _ : state) {
    encode_image(encoder, src.data(), dst.data(), threads);
    benchmark::ClobberMemory();
  }
  double bytes_per_pass = double(kWidth) * kHeight * (12 + 3);
  state.counters["GB/s"] = benchmark::Counter(bytes_per_pass * double(state.iterations()) / 1e9,
                                              benchmark::Counter::kIsRate);
  state.counters["fast_path"] = encoder.uses_fast_path();
}

void BM_Lin709ToP3_U8(benchmark::State& state) {
  run(state, obscura::Dither::kNone);
}
void BM_Lin709ToP3_U8_BlueNoise(benchmark::State& state) {
  run(state, obscura::Dither::kBlueNoise);
}
void BM_Lin709ToP3_U8_Bayer(benchmark::State& state) {
  run(state, obscura::Dither::kBayer);
}

// The same image to Display P3 as float RGB through convert_pixels, the double-precision path of
// `obscura color convert` and Python's convert(), on TBB chunks of 4096 pixels as Python runs it:
// the C++ side of bench/python_overhead.py's convert row.
void BM_ConvertLin709ToP3_F32(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
  const obscura::ColorSpaceInfo& from = obscura::color_space("srgb-linear");
  const obscura::ColorSpaceInfo& to = obscura::color_space("display-p3");
  const std::vector<float>& src = input();
  std::vector<float> dst(src.size());
  const size_t pixels = src.size() / 3;
  for (auto _ : state) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, pixels, 4096),
                      [&](const tbb::blocked_range<size_t>& r) {
                        obscura::convert_pixels(from, to, src.data() + 3 * r.begin(),
                                                dst.data() + 3 * r.begin(), r.size());
                      });
    benchmark::ClobberMemory();
  }
}

}  // namespace

BENCHMARK(BM_Lin709ToP3_U8)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_Lin709ToP3_U8_BlueNoise)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_Lin709ToP3_U8_Bayer)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_ConvertLin709ToP3_F32)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
