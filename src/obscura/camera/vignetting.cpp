#include "obscura/camera/vignetting.h"

#include <algorithm>
#include <cmath>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

// 1 − D/S_f: how much of a lens point's offset survives to the barrel's plane.
double survival(const Vignetting& v, double focus_distance_mm) {
  return std::isinf(focus_distance_mm) ? 1 : 1 - v.barrel_distance_mm / focus_distance_mm;
}

}  // namespace

double natural_vignetting(Point2d w) {
  double sec2 = 1 + w.x * w.x + w.y * w.y;  // 1 / cos²θ
  return 1 / (sec2 * sec2);
}

bool passes_barrel(const Vignetting& v, Point2d l, Point2d w, double focus_distance_mm) {
  if (!v.mechanical()) return true;
  double k = survival(v, focus_distance_mm);
  double x = l.x * k + w.x * v.barrel_distance_mm, y = l.y * k + w.y * v.barrel_distance_mm;
  double r = 0.5 * v.barrel_diameter_mm;
  return x * x + y * y <= r * r;
}

ApertureChords aperture_chords(const Aperture& aperture) {
  ApertureChords table;
  for (int i = 0; i < ApertureChords::kStrips; ++i)
    table.chords[i] = aperture_chord(aperture, -1 + (i + 0.5) * 2.0 / ApertureChords::kStrips);
  return table;
}

double barrel_transmission(const Vignetting& v, const ApertureChords& aperture,
                           double aperture_radius_mm, Point2d w, double focus_distance_mm) {
  if (!v.mechanical()) return 1;
  // The kept lens points, in units of the aperture's radius: a disc (the barrel seen from the
  // focus point) of radius rho centred at c.
  double k = survival(v, focus_distance_mm);
  double rho = 0.5 * v.barrel_diameter_mm / (k * aperture_radius_mm);
  Point2d c(-w.x * v.barrel_distance_mm / (k * aperture_radius_mm),
            -w.y * v.barrel_distance_mm / (k * aperture_radius_mm));
  double d = std::hypot(c.x, c.y);
  if (d + 1 <= rho) return 1;  // holds the aperture's circumscribed circle
  if (d >= rho + 1) return 0;  // misses it
  // Kept and whole aperture, summed over the same vertical strips (the same chords: exactly 1
  // where the disc holds the aperture).
  double kept = 0, whole = 0;
  for (int i = 0; i < ApertureChords::kStrips; ++i) {
    auto [low, high] = aperture.chords[i];
    if (low >= high) continue;
    whole += high - low;
    double dx = -1 + (i + 0.5) * 2.0 / ApertureChords::kStrips - c.x;
    if (std::abs(dx) >= rho) continue;
    double h = std::sqrt(rho * rho - dx * dx);
    kept += std::max(0.0, std::min(high, c.y + h) - std::max(low, c.y - h));
  }
  return whole > 0 ? kept / whole : 0;
}

void validate(const Vignetting& v, double aperture_diameter_mm, double focus_distance_mm) {
  if (!(v.barrel_diameter_mm >= 0) || !std::isfinite(v.barrel_diameter_mm))
    throw Error("camera.vignetting.barrel_diameter_mm",
                "must be 0 (no barrel) or positive; got " + number_text(v.barrel_diameter_mm));
  if (!v.mechanical()) return;
  if (!(v.barrel_distance_mm >= 0) || !std::isfinite(v.barrel_distance_mm))
    throw Error("camera.vignetting.barrel_distance_mm",
                "must be 0 or positive; got " + number_text(v.barrel_distance_mm));
  if (v.barrel_diameter_mm < aperture_diameter_mm)
    throw Error("camera.vignetting.barrel_diameter_mm",
                "must be at least the aperture diameter (" + number_text(aperture_diameter_mm) +
                    " mm), or it would be the aperture and darken the image centre; got " +
                    number_text(v.barrel_diameter_mm));
  if (!(v.barrel_distance_mm < focus_distance_mm))
    throw Error("camera.vignetting.barrel_distance_mm",
                "must be short of the focus distance (" + number_text(focus_distance_mm) +
                    " mm); got " + number_text(v.barrel_distance_mm));
}

}  // namespace obscura
