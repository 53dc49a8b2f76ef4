#include "obscura/shading/ggx_energy.h"

#include <algorithm>
#include <array>
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

constexpr double kPi = std::numbers::pi;
constexpr int kMuSize = 64, kRoughnessSize = 32;
// Below this width the lobe is a mirror for every purpose here (and the quadrature's
// substitution stays well conditioned).
constexpr double kMinAlpha = 1e-4;

double smith_lambda(double c, double alpha) {
  double c2 = c * c;
  return 0.5 * (std::sqrt(1 + alpha * alpha * (1 - c2) / c2) - 1);
}

struct Albedo {
  double e1 = 0, e5 = 0;
};

// ∫ D·G/(4 μo μi) μi dωi (and with (1 − v·h)⁵) for wo at cos θ = mu. With dωi = 4 (wo·h) dωh
// the integrand is D(h) G (wo·h) / μo; drawing h by u = tan²θh / (α² + tan²θh) and φ makes
// D cos θh dωh = du dφ / 2π, so what is left, G (wo·h) / (μo cos θh), is smooth in (u, φ).
Albedo integrate(double mu, double alpha) {
  static const GaussLegendre<32> gu;
  static const GaussLegendre<16> gphi;
  const double sin_o = std::sqrt(std::max(0.0, 1 - mu * mu));
  const double lambda_o = smith_lambda(mu, alpha);
  Albedo a;
  for (int i = 0; i < 32; ++i) {
    double u = gu.x[i], tan2 = alpha * alpha * u / (1 - u);
    double cos_h = 1 / std::sqrt(1 + tan2), sin_h = std::sqrt(tan2) * cos_h;
    for (int j = 0; j < 16; ++j) {
      double phi = kPi * gphi.x[j];  // wo lies in the xz-plane: φ ∈ (0, π) is half of it
      double hx = sin_h * std::cos(phi), hz = cos_h;
      double o_h = sin_o * hx + mu * hz;
      if (o_h <= 0) continue;
      double wi_z = 2 * o_h * hz - mu;
      if (wi_z <= 0) continue;
      double g = 1 / (1 + lambda_o + smith_lambda(wi_z, alpha));
      double value = gu.w[i] * gphi.w[j] * g * o_h / (mu * cos_h);  // × 2 halves / 2π · π
      double m = 1 - o_h, m5 = m * m * m * m * m;
      a.e1 += value, a.e5 += value * m5;
    }
  }
  return a;
}

struct Tables {
  float e1[kRoughnessSize][kMuSize], e5[kRoughnessSize][kMuSize];
  float average1[kRoughnessSize], average5[kRoughnessSize];
};

double node_mu(int i) {
  return (i + 0.5) / kMuSize;
}
double node_alpha(int j) {
  double r = double(j) / (kRoughnessSize - 1);
  return std::max(r * r, kMinAlpha);
}

const Tables& tables() {
  // Integrated once; later runs read it from the cache folder (math/disk_cache.h).
  static const Tables t =
      cached_table<Tables>(std::string("ggx-energy-") + OBSCURA_TABLE_KEY + ".bin", [] {
        Tables t;
        static const GaussLegendre<32> gmu;
        for (int j = 0; j < kRoughnessSize; ++j) {
          double alpha = node_alpha(j);
          for (int i = 0; i < kMuSize; ++i) {
            Albedo a = integrate(node_mu(i), alpha);
            t.e1[j][i] = float(a.e1), t.e5[j][i] = float(a.e5);
          }
          double s1 = 0, s5 = 0;  // 2 ∫ E(μ) μ dμ
          for (int k = 0; k < 32; ++k) {
            Albedo a = integrate(gmu.x[k], alpha);
            s1 += gmu.w[k] * a.e1 * gmu.x[k], s5 += gmu.w[k] * a.e5 * gmu.x[k];
          }
          t.average1[j] = float(2 * s1), t.average5[j] = float(2 * s5);
        }
        return t;
      });
  return t;
}

// Bilinear lookup at (μ, √α); clamped at the grid's edges.
float lookup(const float (&table)[kRoughnessSize][kMuSize], float mu, float alpha) {
  // NaN-safe (math/safe_index.h): a NaN cosine or roughness reads the grid's first cell.
  float x = clamp_or_low(mu * kMuSize - 0.5f, 0.f, float(kMuSize - 1));
  float y = clamp_or_low(std::sqrt(clamp_or_low(alpha, 0.f, 1.f)) * (kRoughnessSize - 1), 0.f,
                         float(kRoughnessSize - 1));
  int x0 = std::min(int(x), kMuSize - 2), y0 = std::min(int(y), kRoughnessSize - 2);
  float fx = x - x0, fy = y - y0;
  float top = table[y0][x0] * (1 - fx) + table[y0][x0 + 1] * fx;
  float bottom = table[y0 + 1][x0] * (1 - fx) + table[y0 + 1][x0 + 1] * fx;
  return top * (1 - fy) + bottom * fy;
}

float lookup(const float (&table)[kRoughnessSize], float alpha) {
  float y = clamp_or_low(std::sqrt(clamp_or_low(alpha, 0.f, 1.f)) * (kRoughnessSize - 1), 0.f,
                         float(kRoughnessSize - 1));
  int y0 = std::min(int(y), kRoughnessSize - 2);
  float fy = y - y0;
  return table[y0] * (1 - fy) + table[y0 + 1] * fy;
}

}  // namespace

float ggx_albedo(float mu, float alpha) {
  return lookup(tables().e1, mu, alpha);
}

float ggx_average_albedo(float alpha) {
  return lookup(tables().average1, alpha);
}

float ggx_schlick_albedo(float f0, float mu, float alpha) {
  return f0 * ggx_albedo(mu, alpha) + (1 - f0) * lookup(tables().e5, mu, alpha);
}

float ggx_schlick_average_albedo(float f0, float alpha) {
  return f0 * ggx_average_albedo(alpha) + (1 - f0) * lookup(tables().average5, alpha);
}

float ggx_multiple_scattering(float mu_o, float mu_i, float alpha) {
  float lost = 1 - ggx_average_albedo(alpha);
  if (lost < 1e-4f) return 0;  // a near-mirror loses nothing worth a lobe
  return (1 - ggx_albedo(mu_o, alpha)) * (1 - ggx_albedo(mu_i, alpha)) *
         (std::numbers::inv_pi_v<float> / lost);
}

Rgb multiple_scattering_color(Rgb f_avg, float alpha) {
  float e = ggx_average_albedo(alpha);
  Rgb result;
  for (int c = 0; c < 3; ++c) result[c] = f_avg[c] * f_avg[c] * e / (1 - f_avg[c] * (1 - e));
  return result;
}

Rgb schlick_average(Rgb f0) {
  return f0 + (Rgb(1.f) - f0) * (1.f / 21);
}

}  // namespace obscura::shading
