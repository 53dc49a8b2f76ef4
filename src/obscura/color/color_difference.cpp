#include "obscura/color/color_difference.h"

#include <cmath>
#include <numbers>

namespace obscura {

namespace {

constexpr double kDegrees = 180 / std::numbers::pi;

double radians(double degrees) {
  return degrees / kDegrees;
}

// Hue angle in degrees [0, 360); 0 for a neutral (a′ = b = 0), as Sharma et al. note (eq. 7).
double hue_degrees(double a, double b) {
  if (a == 0 && b == 0) return 0;
  const double h = std::atan2(b, a) * kDegrees;
  return h < 0 ? h + 360 : h;
}

// C^7 / (C^7 + 25^7) under the square root of G and R_C.
double chroma_weight(double c) {
  const double c7 = std::pow(c, 7);
  return std::sqrt(c7 / (c7 + 6103515625.0));  // 25^7
}

}  // namespace

double delta_e_2000(const Vec3d& lab1, const Vec3d& lab2, const DeltaE2000Weights& weights) {
  const auto [l1, a1, b1] = lab1;
  const auto [l2, a2, b2] = lab2;
  // 1. a′ stretched by G for low-chroma colours, then C′ and h′ (eqs. 2–7).
  const double mean_chroma = (std::hypot(a1, b1) + std::hypot(a2, b2)) / 2;
  const double g = 0.5 * (1 - chroma_weight(mean_chroma));
  const double a1p = (1 + g) * a1, a2p = (1 + g) * a2;
  const double c1p = std::hypot(a1p, b1), c2p = std::hypot(a2p, b2);
  const double h1p = hue_degrees(a1p, b1), h2p = hue_degrees(a2p, b2);
  // 2. ΔL′, ΔC′, ΔH′ (eqs. 8–11): the hue difference taken the short way round.
  const double dl = l2 - l1, dc = c2p - c1p;
  double dh = 0;
  if (c1p * c2p != 0) {
    dh = h2p - h1p;
    if (dh > 180) dh -= 360;
    if (dh < -180) dh += 360;
  }
  const double dhh = 2 * std::sqrt(c1p * c2p) * std::sin(radians(dh / 2));
  // 3. Means and weighting functions (eqs. 12–22); the mean hue across 0°/360° per eq. 14.
  const double lm = (l1 + l2) / 2, cm = (c1p + c2p) / 2;
  double hm = h1p + h2p;
  if (c1p * c2p != 0) {
    if (std::abs(h1p - h2p) <= 180)
      hm /= 2;
    else
      hm = hm < 360 ? (hm + 360) / 2 : (hm - 360) / 2;
  }
  const double t = 1 - 0.17 * std::cos(radians(hm - 30)) + 0.24 * std::cos(radians(2 * hm)) +
                   0.32 * std::cos(radians(3 * hm + 6)) - 0.20 * std::cos(radians(4 * hm - 63));
  const double rotation = 30 * std::exp(-std::pow((hm - 275) / 25, 2));
  const double rt = -std::sin(radians(2 * rotation)) * 2 * chroma_weight(cm);
  const double lm50 = (lm - 50) * (lm - 50);
  const double sl = 1 + 0.015 * lm50 / std::sqrt(20 + lm50);
  const double sc = 1 + 0.045 * cm, sh = 1 + 0.015 * cm * t;
  // 4. The difference (eq. 22).
  const double x = dl / (weights.lightness * sl), y = dc / (weights.chroma * sc),
               z = dhh / (weights.hue * sh);
  return std::sqrt(x * x + y * y + z * z + rt * y * z);
}

}  // namespace obscura
