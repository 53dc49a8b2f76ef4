#include "obscura/shading/charlie_sheen.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/disk_cache.h"
#include "obscura/math/safe_index.h"
#include "obscura/shading/gauss_legendre.h"

#ifndef OBSCURA_TABLE_KEY  // names this file's entries in the cache folder by the code that made
                           // them
#error "OBSCURA_TABLE_KEY comes from cmake/table_key.cmake"
#endif

namespace obscura::shading {

namespace {

constexpr int kMuSize = 32, kRoughnessSize = 32;

// Estevez & Kulla's fit of ln Λ, its five coefficients interpolated between α = 1 and α = 0 in
// t = (1 − α)² (the published values).
template <typename T>
T log_lambda_fit(T x, T alpha) {
  T t = (1 - alpha) * (1 - alpha);
  auto mix = [t](T a, T b) { return a + (b - a) * t; };
  T a = mix(T(21.5473), T(25.3245)), b = mix(T(3.82987), T(3.32435)),
    c = mix(T(0.19823), T(0.16801)), d = mix(T(-1.97760), T(-1.27393)),
    e = mix(T(-4.32054), T(-4.85967));
  return a / (1 + b * std::pow(x, c)) + d * x + e;
}

template <typename T>
T lambda(T mu, T alpha) {
  // The fit is made for μ < ½ and mirrored about it, which keeps Λ smooth up to the normal.
  return mu < T(0.5) ? std::exp(log_lambda_fit(mu, alpha))
                     : std::exp(2 * log_lambda_fit(T(0.5), alpha) - log_lambda_fit(1 - mu, alpha));
}

template <typename T>
T distribution(T cos_h, T alpha) {
  T sin2 = std::max(T(0), 1 - cos_h * cos_h);
  return (2 + 1 / alpha) * std::pow(sin2, T(0.5) / alpha) / (2 * std::numbers::pi_v<T>);
}

// E(μo) = ∫ f μi dωi = 2 ∫₀^π dφ ∫₀¹ f μi dμi with wo in the xz-plane (f is even in φ). The
// lobe leans to grazing μi where it is narrow, so μi = s² spreads the nodes there.
double integrate(double mu_o, double alpha) {
  static const GaussLegendre<48> gs;
  static const GaussLegendre<24> gphi;
  const double sin_o = std::sqrt(std::max(0.0, 1 - mu_o * mu_o));
  const double lambda_o = lambda(mu_o, alpha);
  double sum = 0;
  for (int i = 0; i < 48; ++i) {
    double s = gs.x[i], mu_i = s * s, sin_i = std::sqrt(std::max(0.0, 1 - mu_i * mu_i));
    double lambda_i = lambda(mu_i, alpha);
    for (int j = 0; j < 24; ++j) {
      double phi = std::numbers::pi * gphi.x[j];
      // |wo + wi|² = 2 + 2 wo·wi, and cos θh = (μo + μi) / |wo + wi|.
      double o_i = sin_o * sin_i * std::cos(phi) + mu_o * mu_i;
      double cos_h = (mu_o + mu_i) / std::sqrt(std::max(2 + 2 * o_i, 1e-300));
      // f μi = D / ((1 + Λo + Λi) 4 μo); dμi = 2s ds, dφ = π dx, and the factor 2 for φ < 0.
      double f_mu_i = distribution(cos_h, alpha) / ((1 + lambda_o + lambda_i) * 4 * mu_o);
      sum += gs.w[i] * gphi.w[j] * f_mu_i * (2 * s) * std::numbers::pi * 2;
    }
  }
  return sum;
}

struct Table {
  float e[kRoughnessSize][kMuSize];
};

const Table& table() {
  // Integrated once; later runs read it from the cache folder (math/disk_cache.h).
  static const Table t =
      cached_table<Table>(std::string("charlie-sheen-") + OBSCURA_TABLE_KEY + ".bin", [] {
        Table t;
        for (int j = 0; j < kRoughnessSize; ++j) {
          double r = double(j) / (kRoughnessSize - 1);
          double alpha = std::max(r * r, double(kMinSheenAlpha));
          for (int i = 0; i < kMuSize; ++i)
            t.e[j][i] = float(integrate((i + 0.5) / kMuSize, alpha));
        }
        return t;
      });
  return t;
}

}  // namespace

float sheen_alpha(float roughness) {
  float r = std::clamp(roughness, 0.f, 1.f);
  return std::max(r * r, kMinSheenAlpha);
}

float charlie_distribution(float cos_h, float alpha) {
  return distribution(cos_h, alpha);
}

float charlie_lambda(float mu, float alpha) {
  return lambda(std::clamp(mu, 0.f, 1.f), alpha);
}

float charlie_sheen(float mu_o, float mu_i, float cos_h, float alpha) {
  if (mu_o <= 0 || mu_i <= 0) return 0;
  return distribution(cos_h, alpha) /
         ((1 + charlie_lambda(mu_o, alpha) + charlie_lambda(mu_i, alpha)) * 4 * mu_o * mu_i);
}

float sheen_albedo(float mu, float alpha) {
  // Bilinear at (μ, √α), clamped at the grid's edges.
  const Table& t = table();
  // NaN-safe (math/safe_index.h): a NaN cosine or roughness reads the grid's first cell.
  float x = clamp_or_low(mu * kMuSize - 0.5f, 0.f, float(kMuSize - 1));
  float y = clamp_or_low(std::sqrt(clamp_or_low(alpha, 0.f, 1.f)) * (kRoughnessSize - 1), 0.f,
                         float(kRoughnessSize - 1));
  int x0 = std::min(int(x), kMuSize - 2), y0 = std::min(int(y), kRoughnessSize - 2);
  float fx = x - x0, fy = y - y0;
  float top = t.e[y0][x0] * (1 - fx) + t.e[y0][x0 + 1] * fx;
  float bottom = t.e[y0 + 1][x0] * (1 - fx) + t.e[y0 + 1][x0 + 1] * fx;
  return top * (1 - fy) + bottom * fy;
}

}  // namespace obscura::shading
