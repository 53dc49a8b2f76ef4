#include "obscura/camera/lens_prescription.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

bool LensSurface::is_aspheric() const {
  if (conic != 0) return true;
  for (double a : aspheric)
    if (a != 0) return true;
  return false;
}

double refractive_index(double n_d, double abbe_number, double wavelength_nm) {
  if (abbe_number <= 0 || n_d <= 1) return n_d;
  auto inverse_square = [](double lambda) { return 1 / (lambda * lambda); };
  double b =
      (n_d - 1) / abbe_number / (inverse_square(kWavelengthF_nm) - inverse_square(kWavelengthC_nm));
  return n_d + b * (inverse_square(wavelength_nm) - inverse_square(kWavelengthD_nm));
}

bool surface_sag(const LensSurface& s, double r_mm, Sag& out) {
  double r2 = r_mm * r_mm;
  out = {};
  if (s.radius_mm != 0) {
    double c = 1 / s.radius_mm;
    double root_term = 1 - (1 + s.conic) * c * c * r2;
    if (root_term < 0) return false;
    double root = std::sqrt(root_term);
    out.z = c * r2 / (1 + root);
    // d/dr of c·r²/(1 + √(1 − (1+k)c²r²)) simplifies to c·r / √(1 − (1+k)c²r²).
    if (root == 0) return false;  // the conic's rim: a vertical tangent
    out.slope = c * r_mm / root;
  }
  // A4·r⁴ + … + A16·r¹⁶ and its derivative, by Horner's rule in r².
  double poly = 0, dpoly = 0;
  for (int i = int(s.aspheric.size()) - 1; i >= 0; --i) {
    int power = 4 + 2 * i;
    poly = poly * r2 + s.aspheric[size_t(i)];
    dpoly = dpoly * r2 + power * s.aspheric[size_t(i)];
  }
  out.z += poly * r2 * r2;
  out.slope += dpoly * r2 * r_mm;
  return true;
}

int stop_index(const LensPrescription& p) {
  for (size_t i = 0; i < p.surfaces.size(); ++i)
    if (p.surfaces[i].is_stop) return int(i);
  return -1;
}

void validate(const LensSurface& s) {
  auto finite = [&](const char* field, double v) {
    if (!std::isfinite(v)) throw Error(field, "must be a finite number");
  };
  finite("radius_mm", s.radius_mm);
  finite("thickness_mm", s.thickness_mm);
  finite("n_d", s.n_d);
  finite("V_d", s.abbe_number);
  finite("aperture_diameter_mm", s.aperture_diameter_mm);
  finite("conic", s.conic);
  static constexpr const char* kAsphericNames[] = {"A4", "A6", "A8", "A10", "A12", "A14", "A16"};
  for (size_t i = 0; i < s.aspheric.size(); ++i) finite(kAsphericNames[i], s.aspheric[i]);
  if (!(s.aperture_diameter_mm > 0))
    throw Error("aperture_diameter_mm",
                "must be positive; got " + number_text(s.aperture_diameter_mm));
  if (s.thickness_mm < 0)
    throw Error("thickness_mm", "must not be negative; got " + number_text(s.thickness_mm));
  if (s.n_d < 1) throw Error("n_d", "must be at least 1 (air); got " + number_text(s.n_d));
  if (s.abbe_number < 0)
    throw Error("V_d", "must be positive, or 0 for none; got " + number_text(s.abbe_number));
  if (s.is_stop && (s.radius_mm != 0 || s.is_aspheric()))
    throw Error("radius_mm", "the aperture stop must be flat (radius 0, no asphere)");
  if (s.is_stop && s.n_d != 1) throw Error("n_d", "the aperture stop must have air after it");
}

void validate(const LensPrescription& p) {
  const std::string lens = "lens '" + p.name + "'";
  if (p.surfaces.empty()) throw Error(lens, "has no surfaces");
  int stops = 0;
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    try {
      validate(p.surfaces[i]);
    } catch (const Error& e) {
      throw Error(lens + " surface " + std::to_string(i + 1), e.what());
    }
    stops += p.surfaces[i].is_stop;
  }
  if (stops != 1)
    throw Error(lens, "needs exactly one aperture stop (a row with radius 0 and n_d 0); it has " +
                          std::to_string(stops));
  if (int(p.surfaces.size()) == stops) throw Error(lens, "has no refracting surface");
  if (p.surfaces.back().n_d != 1)
    throw Error(lens + " surface " + std::to_string(p.surfaces.size()),
                "the last surface must have air (n_d 1) after it, towards the sensor");
}

}  // namespace obscura
