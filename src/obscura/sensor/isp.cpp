#include "obscura/sensor/isp.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <string>

#include "obscura/math/request_error.h"

namespace obscura {

namespace {

using Kernel = double[5][5];

// The four interpolations a Bayer mosaic needs, as 5 × 5 kernels centred on the pixel (row =
// dy + 2, column = dx + 2): green at a red or blue pixel; red (or blue) at a green pixel whose
// row holds it; the same where its column holds it; red at blue (and blue at red).
struct KernelSet {
  Kernel green_at_rb, along_row, along_column, diagonal;
};

// Bilinear: the means of the nearest same-colour neighbours.
constexpr KernelSet kBilinear = {
    {{0, 0, 0, 0, 0}, {0, 0, .25, 0, 0}, {0, .25, 0, .25, 0}, {0, 0, .25, 0, 0}, {0, 0, 0, 0, 0}},
    {{0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {0, .5, 0, .5, 0}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}},
    {{0, 0, 0, 0, 0}, {0, 0, .5, 0, 0}, {0, 0, 0, 0, 0}, {0, 0, .5, 0, 0}, {0, 0, 0, 0, 0}},
    {{0, 0, 0, 0, 0}, {0, .25, 0, .25, 0}, {0, 0, 0, 0, 0}, {0, .25, 0, .25, 0}, {0, 0, 0, 0, 0}},
};

// Malvar, He & Cutler, "High-quality linear interpolation for demosaicing of Bayer-patterned
// color images" (ICASSP 2004), figure 2: the bilinear estimate plus a gain times the known
// colour's Laplacian, as 5 × 5 filters (the paper's coefficients, divided by 8).
constexpr KernelSet kMalvar = {
    {{0, 0, -1. / 8, 0, 0},
     {0, 0, 2. / 8, 0, 0},
     {-1. / 8, 2. / 8, 4. / 8, 2. / 8, -1. / 8},
     {0, 0, 2. / 8, 0, 0},
     {0, 0, -1. / 8, 0, 0}},
    {{0, 0, .5 / 8, 0, 0},
     {0, -1. / 8, 0, -1. / 8, 0},
     {-1. / 8, 4. / 8, 5. / 8, 4. / 8, -1. / 8},
     {0, -1. / 8, 0, -1. / 8, 0},
     {0, 0, .5 / 8, 0, 0}},
    {{0, 0, -1. / 8, 0, 0},
     {0, -1. / 8, 4. / 8, -1. / 8, 0},
     {.5 / 8, 0, 5. / 8, 0, .5 / 8},
     {0, -1. / 8, 4. / 8, -1. / 8, 0},
     {0, 0, -1. / 8, 0, 0}},
    {{0, 0, -1.5 / 8, 0, 0},
     {0, 2. / 8, 0, 2. / 8, 0},
     {-1.5 / 8, 0, 6. / 8, 0, -1.5 / 8},
     {0, 2. / 8, 0, 2. / 8, 0},
     {0, 0, -1.5 / 8, 0, 0}},
};

// Mirrors an index into [0, n): −1 → 1, n → n − 2, which keeps the CFA's parity.
int mirror(int i, int n) {
  if (n == 1) return 0;
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * (n - 1) - i;
  return i;
}

}  // namespace

DemosaicMethod parse_demosaic_method(std::string_view text) {
  if (text == "bilinear") return DemosaicMethod::kBilinear;
  if (text == "malvar") return DemosaicMethod::kMalvar;
  throw RequestError("demosaic", "expected bilinear or malvar; got '" + std::string(text) + "'");
}

Image demosaic(const Image& mosaic, CfaPattern cfa, DemosaicMethod method) {
  if (mosaic.channels != 1) throw Error("demosaic", "expects a one-channel mosaic");
  Image rgb(mosaic.width, mosaic.height, 3);
  const KernelSet& kernels = method == DemosaicMethod::kMalvar ? kMalvar : kBilinear;
  const int w = mosaic.width, h = mosaic.height;
  auto apply = [&](const Kernel& kernel, int x, int y) {
    double sum = 0;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx)
        if (double weight = kernel[dy + 2][dx + 2])
          sum += weight * mosaic.at(mirror(x + dx, w), mirror(y + dy, h), 0);
    return float(sum);
  };
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const float value = mosaic.at(x, y, 0);
      if (cfa == CfaPattern::kMonochrome) {
        for (int c = 0; c < 3; ++c) rgb.at(x, y, c) = value;
        continue;
      }
      const int k = cfa_color(cfa, x, y);
      for (int j = 0; j < 3; ++j) {
        float out = value;
        if (j != k) {
          if (j == 1)
            out = apply(kernels.green_at_rb, x, y);
          else if (k == 1)
            out = apply(cfa_color(cfa, x + 1, y) == j ? kernels.along_row : kernels.along_column, x,
                        y);
          else
            out = apply(kernels.diagonal, x, y);
        }
        rgb.at(x, y, j) = out;
      }
    }
  });
  return rgb;
}

Image develop_raw(const RawCapture& capture, DemosaicMethod method) {
  Image mosaic(capture.width, capture.height, 1);
  for (size_t i = 0; i < capture.raw.size(); ++i)
    mosaic.data[i] = float((capture.raw[i] - capture.black_level) / capture.gain_dn_per_e);
  Image camera = demosaic(mosaic, capture.cfa, method);
  if (capture.cfa == CfaPattern::kMonochrome) {
    // One channel: its electrons per film unit of white are the only calibration.
    for (float& v : camera.data) v = float(v / capture.electrons_per_film);
    return camera;
  }
  // White balance then the colour-correction matrix; together they are the inverse of the
  // sensor's projection (film → electrons per lux·s·m²), scaled to film units.
  const Vec3d neutral = capture.response.neutral_d65;
  Matrix3d ccm = capture.response.electrons_per_lux_s_m2.inverse() * Matrix3d::diagonal(neutral);
  const Matrix3d& m = capture.response.electrons_per_lux_s_m2;
  const double per_film_green = m.m[1][0] + m.m[1][1] + m.m[1][2];
  const double scale = per_film_green / capture.electrons_per_film;
  Image out(capture.width, capture.height, 3);
  out.channel_names = {"R", "G", "B"};
  for (size_t p = 0; p < size_t(capture.width) * capture.height; ++p) {
    Vec3d balanced;
    for (int c = 0; c < 3; ++c) balanced[size_t(c)] = camera.data[3 * p + c] / neutral[size_t(c)];
    const Vec3d film = ccm * balanced;
    for (int c = 0; c < 3; ++c) out.data[3 * p + c] = float(film[size_t(c)] * scale);
  }
  return out;
}

}  // namespace obscura
