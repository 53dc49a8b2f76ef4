#include "obscura/color/rgb_to_spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include <tbb/parallel_for.h>

#include "obscura/color/spectral.h"
#include "obscura/color/spectral_working_space.h"
#include "obscura/math/disk_cache.h"

#ifndef OBSCURA_TABLE_KEY  // names this file's entries in the cache folder by the code that made
                           // them
#error "OBSCURA_TABLE_KEY comes from cmake/table_key.cmake"
#endif

namespace obscura {

namespace {

constexpr int kRes = RgbToSpectrumTable::kResolution;
constexpr double kFirstNm = 360, kSpanNm = 470;

double smoothstep(double x) {
  return x * x * (3 - 2 * x);
}

// CIELAB of XYZ relative to `white` (CIE 15), and its Jacobian d(L, a, b)/d(X, Y, Z).
struct Lab {
  Vec3d value;
  Matrix3d jacobian;
};

Lab lab_of(const Vec3d& xyz, const Vec3d& white) {
  constexpr double delta = 6.0 / 29;
  Vec3d f{}, df{};
  for (int i = 0; i < 3; ++i) {
    double q = xyz[i] / white[i];
    if (q > delta * delta * delta) {
      f[i] = std::cbrt(q);
      df[i] = 1 / (3 * f[i] * f[i] * white[i]);
    } else {
      f[i] = q / (3 * delta * delta) + 4.0 / 29;
      df[i] = 1 / (3 * delta * delta * white[i]);
    }
  }
  Lab lab;
  lab.value = {116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])};
  lab.jacobian = {
      {{{0, 116 * df[1], 0}, {500 * df[0], -500 * df[1], 0}, {0, 200 * df[1], -200 * df[2]}}}};
  return lab;
}

// The colour integral discretised for the fit: s(λ) is taken as linear between nodes every
// kNodeStepNm, so XYZ = Σ s(node)·weight(node) with weights that integrate the 1 nm observer ×
// illuminant tables exactly against that interpolation.
constexpr int kNodeStepNm = 5;
constexpr int kNodes = int(kSpanNm) / kNodeStepNm + 1;

struct FitData {
  std::array<Vec3d, kNodes> weight{};
  std::array<double, kNodes> t{};  // normalised wavelength of each node
  Matrix3d xyz_from_rgb;
  Vec3d white_xyz;
};

FitData make_fit_data() {
  FitData d;
  for (int n = 0; n < kNodes; ++n) d.t[n] = double(n * kNodeStepNm) / kSpanNm;
  for (int nm = int(kFirstNm); nm <= int(kFirstNm + kSpanNm); ++nm) {
    Vec3d xyz = cmf_xyz(nm);
    double light = working_illuminant(nm);
    double position = (nm - kFirstNm) / kNodeStepNm;
    int n = std::min(int(position), kNodes - 2);
    double f = position - n;
    for (int c = 0; c < 3; ++c) {
      d.weight[n][c] += (1 - f) * xyz[c] * light;
      d.weight[n + 1][c] += f * xyz[c] * light;
    }
  }
  d.xyz_from_rgb = working_rgb_from_xyz().inverse();
  d.white_xyz = d.xyz_from_rgb * Vec3d{1, 1, 1};
  return d;
}

// Lab of the spectrum of coefficients c, and its Jacobian with respect to c.
Lab spectrum_lab(const FitData& d, const Vec3d& c) {
  Vec3d xyz{};
  Matrix3d dxyz{};  // d XYZ / d c
  for (int n = 0; n < kNodes; ++n) {
    double t = d.t[n];
    double x = (c[0] * t + c[1]) * t + c[2];
    double root = std::sqrt(1 + x * x);
    double s = 0.5 + x / (2 * root);
    double ds = 1 / (2 * root * root * root);
    Vec3d dc{ds * t * t, ds * t, ds};
    for (int i = 0; i < 3; ++i) {
      xyz[i] += s * d.weight[n][i];
      for (int k = 0; k < 3; ++k) dxyz.m[i][k] += dc[k] * d.weight[n][i];
    }
  }
  Lab lab = lab_of(xyz, d.white_xyz);
  lab.jacobian = lab.jacobian * dxyz;
  return lab;
}

double norm(const Vec3d& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// Gauss–Newton (the system is square: three residuals, three unknowns) from `c`, halving steps
// that do not reduce the residual. Returns the final ΔE.
double fit_point(const FitData& d, const Vec3d& rgb, Vec3d& c) {
  Vec3d target = lab_of(d.xyz_from_rgb * rgb, d.white_xyz).value;
  auto residual_of = [&](const Lab& lab) {
    return Vec3d{target[0] - lab.value[0], target[1] - lab.value[1], target[2] - lab.value[2]};
  };
  Lab lab = spectrum_lab(d, c);
  Vec3d r = residual_of(lab);
  double error = norm(r);
  for (int iteration = 0; iteration < 50 && error > 1e-6; ++iteration) {
    double det = 0;
    {
      const auto& m = lab.jacobian.m;
      det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }
    if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) break;
    Vec3d step = lab.jacobian.inverse() * r;
    bool improved = false;
    for (double scale = 1; scale > 1e-4; scale *= 0.5) {
      Vec3d next{c[0] + scale * step[0], c[1] + scale * step[1], c[2] + scale * step[2]};
      Lab next_lab = spectrum_lab(d, next);
      Vec3d next_r = residual_of(next_lab);
      double next_error = norm(next_r);
      if (next_error < error && std::isfinite(next_error)) {
        c = next, lab = next_lab, r = next_r, error = next_error;
        improved = true;
        break;
      }
    }
    if (!improved) break;
  }
  return error;
}

}  // namespace

float SigmoidPolynomial::operator()(float nm) const {
  // In float (it runs for every colour at every hit): x² overflows only where S is 0 or 1 anyway.
  float t = (nm - float(kFirstNm)) * (1 / float(kSpanNm));
  float x = (c0 * t + c1) * t + c2;
  if (!(std::abs(x) < 1e18f)) return x > 0 ? 1.f : 0.f;
  return 0.5f + 0.5f * x / std::sqrt(1 + x * x);
}

const RgbToSpectrumTable& RgbToSpectrumTable::working_space() {
  static const RgbToSpectrumTable& table = cached_or_fitted();
  return table;
}

// The cache entry: the scale values, the coefficients and the worst ΔE, as the floats they are.
const RgbToSpectrumTable& RgbToSpectrumTable::cached_or_fitted() {
  static RgbToSpectrumTable table;
  const std::string name = std::string("rgb-to-spectrum-") + OBSCURA_TABLE_KEY + ".bin";
  const size_t count = size_t(kRes) + size_t(3) * kRes * kRes * kRes * 3 + 1;
  if (std::optional<std::vector<std::byte>> bytes =
          read_cached_table(name, count * sizeof(float))) {
    std::vector<float> floats(count);
    std::memcpy(floats.data(), bytes->data(), bytes->size());
    std::copy_n(floats.begin(), kRes, table.scale_.begin());
    table.coefficients_.assign(floats.begin() + kRes, floats.end() - 1);
    table.worst_delta_e_ = floats.back();
    return table;
  }
  table = fit();
  std::vector<float> floats(table.scale_.begin(), table.scale_.end());
  floats.insert(floats.end(), table.coefficients_.begin(), table.coefficients_.end());
  floats.push_back(table.worst_delta_e_);
  write_cached_table(name, std::as_bytes(std::span<const float>(floats)));
  return table;
}

RgbToSpectrumTable RgbToSpectrumTable::fit() {
  RgbToSpectrumTable table;
  for (int k = 0; k < kRes; ++k)
    table.scale_[k] = float(smoothstep(smoothstep(double(k) / (kRes - 1))));
  table.coefficients_.assign(size_t(3) * kRes * kRes * kRes * 3, 0.f);
  const FitData data = make_fit_data();
  std::vector<float> worst(size_t(3) * kRes * kRes, 0.f);
  // One column of the largest channel's values per task: walk from a mid-grey-ish start up and
  // down, each fit starting from its neighbour's solution. Columns share nothing, so the table
  // is the same for any number of threads.
  tbb::parallel_for(0, 3 * kRes * kRes, [&](int column) {
    const int largest = column / (kRes * kRes), y = column / kRes % kRes, x = column % kRes;
    auto solve = [&](int k, Vec3d& c) {
      double z = table.scale_[k];
      Vec3d rgb{};
      rgb[largest] = z;
      rgb[(largest + 1) % 3] = z * x / (kRes - 1);
      rgb[(largest + 2) % 3] = z * y / (kRes - 1);
      double error = fit_point(data, rgb, c);
      if (z > 0) worst[column] = std::max(worst[column], float(error));
      float* out = &table.coefficients_[((size_t(largest * kRes + k) * kRes + y) * kRes + x) * 3];
      for (int i = 0; i < 3; ++i) out[i] = float(c[i]);
    };
    const int start = kRes / 5;
    Vec3d c{0, 0, 0};
    for (int k = start; k < kRes; ++k) solve(k, c);
    c = {0, 0, 0};
    for (int k = start; k >= 0; --k) solve(k, c);
  });
  table.worst_delta_e_ = *std::max_element(worst.begin(), worst.end());
  return table;
}

SigmoidPolynomial RgbToSpectrumTable::operator()(Rgb rgb) const {
  for (int i = 0; i < 3; ++i) rgb[i] = std::clamp(rgb[i], 0.f, 1.f);
  if (rgb.r == rgb.g && rgb.g == rgb.b) {
    // The constant spectrum v: S(c₂) = v for c₂ = (v − ½)/√(v(1 − v)).
    float v = rgb.r;
    if (v <= 0) return {0, 0, -std::numeric_limits<float>::infinity()};
    if (v >= 1) return {0, 0, std::numeric_limits<float>::infinity()};
    return {0, 0, float((v - 0.5) / std::sqrt(double(v) * (1 - v)))};
  }
  int largest = rgb.r >= rgb.g ? (rgb.r >= rgb.b ? 0 : 2) : (rgb.g >= rgb.b ? 1 : 2);
  float z = rgb[largest];
  float x = rgb[(largest + 1) % 3] / z * (kRes - 1), y = rgb[(largest + 2) % 3] / z * (kRes - 1);
  int xi = std::min(int(x), kRes - 2), yi = std::min(int(y), kRes - 2);
  int zi = int(std::upper_bound(scale_.begin(), scale_.end(), z) - scale_.begin()) - 1;
  zi = std::clamp(zi, 0, kRes - 2);
  float dx = x - xi, dy = y - yi, dz = (z - scale_[zi]) / (scale_[zi + 1] - scale_[zi]);
  float c[3] = {0, 0, 0};
  for (int corner = 0; corner < 8; ++corner) {
    int ox = corner & 1, oy = corner >> 1 & 1, oz = corner >> 2 & 1;
    float w = (ox ? dx : 1 - dx) * (oy ? dy : 1 - dy) * (oz ? dz : 1 - dz);
    const float* v =
        &coefficients_[((size_t(largest * kRes + zi + oz) * kRes + yi + oy) * kRes + xi + ox) * 3];
    for (int i = 0; i < 3; ++i) c[i] += w * v[i];
  }
  return {c[0], c[1], c[2]};
}

namespace {

Rgb sample(const SigmoidPolynomial& s, const SampledWavelengths& w, float scale) {
  Rgb values;
  for (int i = 0; i < SampledWavelengths::kCount; ++i) values[i] = scale * s(w.nm(i));
  return values;
}

}  // namespace

Rgb lift_reflectance(Rgb rgb, const SampledWavelengths& w) {
  return sample(RgbToSpectrumTable::working_space()(rgb), w, 1);
}

Rgb lift_unbounded(Rgb rgb, const SampledWavelengths& w) {
  for (int i = 0; i < 3; ++i) rgb[i] = std::max(rgb[i], 0.f);
  float scale = 2 * rgb.max_component();
  if (!(scale > 0)) return Rgb();
  return sample(RgbToSpectrumTable::working_space()(rgb / scale), w, scale);
}

Rgb lift_illuminant(Rgb rgb, const SampledWavelengths& w) {
  Rgb values = lift_unbounded(rgb, w);
  for (int i = 0; i < SampledWavelengths::kCount; ++i) values[i] *= w.illuminant(i);
  return values;
}

}  // namespace obscura
