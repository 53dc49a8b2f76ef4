#include "obscura/shading/phong_albedo.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/disk_cache.h"
#include "obscura/math/safe_index.h"
#include "obscura/shading/gauss_legendre.h"
#include "obscura/shading/phong_lobe.h"

#ifndef OBSCURA_TABLE_KEY  // names this file's entries in the cache folder by the code that made
                           // them
#error "OBSCURA_TABLE_KEY comes from cmake/table_key.cmake"
#endif

namespace obscura::shading {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMuSize = 32, kExponentSize = 33;
constexpr double kExponentScale = 8;  // t = n / (n + 8): the grid is dense where E changes
constexpr double kMaxT = 0.9992;      // n ≈ 10⁴

double node_mu(int i) {
  return double(i) / (kMuSize - 1);
}
double node_exponent(int j) {
  const double t = kMaxT * j / (kExponentSize - 1);
  return kExponentScale * t / (1 - t);
}

// A unit vector from spherical angles about the axis `z` with `x` ⟂ z.
struct Frame {
  double x[3], y[3], z[3];
};
Frame frame_about(double zx, double zz) {  // z in the xz-plane
  return {{zz, 0, -zx}, {0, 1, 0}, {zx, 0, zz}};
}

// ∫ c(n) lobeⁿ μi dωi for wo = (sin θo, 0, μ) over the surface with normal (0, 0, 1).
double integrate(double mu, double n, bool blinn) {
  static const GaussLegendre<48> gu;
  static const GaussLegendre<48> gphi;
  const double sin_o = std::sqrt(std::max(0.0, 1 - mu * mu));
  const double wo[3] = {sin_o, 0, mu};
  // The lobe's axis: the mirror direction of wo (Phong), or the normal (Blinn's h).
  const Frame f = blinn ? frame_about(0, 1) : frame_about(-sin_o, mu);
  const double c =
      blinn ? blinn_phong_lobe_normalization(float(n)) : phong_lobe_normalization(float(n));
  double sum = 0;
  for (int i = 0; i < 48; ++i) {
    const double cos_a = std::pow(gu.x[i], 1 / (n + 1)),
                 sin_a = std::sqrt(std::max(0.0, 1 - cos_a * cos_a));
    for (int j = 0; j < 48; ++j) {
      const double phi = 2 * kPi * gphi.x[j];
      const double lx = sin_a * std::cos(phi), ly = sin_a * std::sin(phi);
      double d[3];
      for (int k = 0; k < 3; ++k) d[k] = f.x[k] * lx + f.y[k] * ly + f.z[k] * cos_a;
      double value = 0;
      if (!blinn) {
        value = std::max(0.0, d[2]);  // d is wi; lobeⁿ dωi = du dφ / (n + 1)
      } else {
        // d is h: wi = 2 (wo·h) h − wo, dωi = 4 (wo·h) dωh.
        const double o_h = wo[0] * d[0] + wo[1] * d[1] + wo[2] * d[2];
        const double wi_z = 2 * o_h * d[2] - wo[2];
        if (o_h > 0 && wi_z > 0) value = 4 * o_h * wi_z;
      }
      sum += gu.w[i] * gphi.w[j] * value;
    }
  }
  return c * 2 * kPi * sum / (n + 1);
}

struct Tables {
  float phong[kExponentSize][kMuSize], blinn[kExponentSize][kMuSize];
};

const Tables& tables() {
  // Integrated once; later runs read it from the cache folder (math/disk_cache.h).
  static const Tables t =
      cached_table<Tables>(std::string("phong-albedo-") + OBSCURA_TABLE_KEY + ".bin", [] {
        Tables t;
        for (int j = 0; j < kExponentSize; ++j)
          for (int i = 0; i < kMuSize; ++i) {
            t.phong[j][i] = float(integrate(node_mu(i), node_exponent(j), false));
            t.blinn[j][i] = float(integrate(node_mu(i), node_exponent(j), true));
          }
        return t;
      });
  return t;
}

}  // namespace

float phong_lobe_albedo(float mu, float exponent, bool blinn) {
  const auto& table = blinn ? tables().blinn : tables().phong;
  // NaN-safe (math/safe_index.h): a NaN cosine or exponent reads the grid's first cell.
  const float x = clamp_or_low(mu, 0.f, 1.f) * (kMuSize - 1);
  const float n = clamp_or_low(exponent, 0.f, 1e30f);
  const float t = float(n / (n + kExponentScale) / kMaxT);
  const float y = clamp_or_low(t * (kExponentSize - 1), 0.f, float(kExponentSize - 1));
  const int x0 = std::min(int(x), kMuSize - 2), y0 = std::min(int(y), kExponentSize - 2);
  const float fx = x - x0, fy = y - y0;
  const float top = table[y0][x0] * (1 - fx) + table[y0][x0 + 1] * fx;
  const float bottom = table[y0 + 1][x0] * (1 - fx) + table[y0 + 1][x0 + 1] * fx;
  return top * (1 - fy) + bottom * fy;
}

}  // namespace obscura::shading
