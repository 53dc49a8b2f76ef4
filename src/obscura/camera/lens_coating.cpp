#include "obscura/camera/lens_coating.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

using Complex = std::complex<double>;

// cos θ in a medium of index n for light whose invariant n·sin θ is `invariant`: real below the
// critical angle, +i·√(sin²θ − 1) beyond it (the evanescent wave, decaying into the medium).
Complex cosine_in(double n, double invariant) {
  double sin_theta = invariant / n;
  double c2 = 1 - sin_theta * sin_theta;
  return c2 >= 0 ? Complex(std::sqrt(c2), 0) : Complex(0, std::sqrt(-c2));
}

// Fresnel's amplitude coefficients of one face, from (na, cos_a) into (nb, cos_b).
struct Amplitudes {
  Complex r_s, r_p, t_s, t_p;
};
Amplitudes face(double na, Complex cos_a, double nb, Complex cos_b) {
  const Complex s_sum = na * cos_a + nb * cos_b, p_sum = nb * cos_a + na * cos_b;
  return {(na * cos_a - nb * cos_b) / s_sum, (nb * cos_a - na * cos_b) / p_sum,
          2.0 * na * cos_a / s_sum, 2.0 * na * cos_a / p_sum};
}

double parse_number(const std::string& text, const std::string& field, const char* what) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value))
    throw Error(field, std::string("expected ") + what + " as a number; got '" + text + "'");
  return value;
}

}  // namespace

bool operator==(const LensCoating& a, const LensCoating& b) {
  return a.thickness_nm == b.thickness_nm && a.index == b.index;
}

LensCoating quarter_wave_coating(double index, double design_wavelength_nm) {
  return {.thickness_nm = design_wavelength_nm / (4 * index), .index = index};
}

void validate(const LensCoating& c) {
  if (!(c.thickness_nm >= 0) || !std::isfinite(c.thickness_nm))
    throw Error("camera.coating.thickness_nm",
                "must be 0 (bare glass) or positive; got " + number_text(c.thickness_nm));
  if (!(c.index >= 1) || !std::isfinite(c.index))
    throw Error("camera.coating.index", "must be at least 1; got " + number_text(c.index));
}

LensCoating parse_lens_coating(const std::string& text, const std::string& field) {
  if (text == "none") return {};
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    size_t colon = text.find(':', start);
    parts.push_back(text.substr(start, colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts[0] != "quarter-wave" || parts.size() > 3)
    throw Error(field,
                "expected none, quarter-wave, quarter-wave:INDEX or quarter-wave:INDEX:NM; "
                "got '" +
                    text + "'");
  double index = parts.size() > 1 ? parse_number(parts[1], field, "the layer's index") : 1.38;
  double nm = parts.size() > 2 ? parse_number(parts[2], field, "the design wavelength (nm)") : 550;
  if (!(index >= 1 && index <= 5))
    throw Error(field, "the layer's index must be in [1, 5]; got " + number_text(index));
  if (!(nm >= 200 && nm <= 2000))
    throw Error(field, "the design wavelength must be in [200, 2000] nm; got " + number_text(nm));
  return quarter_wave_coating(index, nm);
}

std::string lens_coating_text(const LensCoating& c) {
  if (!c.coated()) return "none";
  return "quarter-wave:" + number_text(c.index) + ":" + number_text(4 * c.index * c.thickness_nm);
}

InterfaceOptics bare_interface(double n1, double n2, double cos_incidence) {
  const double invariant = n1 * std::sqrt(std::max(0.0, 1 - cos_incidence * cos_incidence));
  const Complex cos1(cos_incidence, 0), cos2 = cosine_in(n2, invariant);
  const Amplitudes a = face(n1, cos1, n2, cos2);
  // Power leaves in the second medium only as a propagating wave: Re(n2·cos θ2).
  const double flux = (n2 * cos2).real() / (n1 * cos_incidence);
  return {std::norm(a.r_s), std::norm(a.r_p), flux * std::norm(a.t_s), flux * std::norm(a.t_p)};
}

InterfaceOptics coated_interface(const LensCoating& coating, double n1, double n2,
                                 double cos_incidence, double wavelength_nm) {
  if (!coating.coated()) return bare_interface(n1, n2, cos_incidence);
  const double nc = coating.index;
  const double invariant = n1 * std::sqrt(std::max(0.0, 1 - cos_incidence * cos_incidence));
  const Complex cos1(cos_incidence, 0), cos_c = cosine_in(nc, invariant),
                                        cos2 = cosine_in(n2, invariant);
  const Amplitudes a = face(n1, cos1, nc, cos_c), b = face(nc, cos_c, n2, cos2);
  // The phase of one pass through the layer; e^{2iδ} for the round trip between its faces.
  const Complex delta = 2 * std::numbers::pi * nc * coating.thickness_nm * cos_c / wavelength_nm;
  const Complex round_trip = std::exp(Complex(0, 2) * delta),
                one_pass = std::exp(Complex(0, 1) * delta);
  auto reflect = [&](Complex ra, Complex rb) {
    return (ra + rb * round_trip) / (1.0 + ra * rb * round_trip);
  };
  auto transmit = [&](Complex ta, Complex tb, Complex ra, Complex rb) {
    return ta * tb * one_pass / (1.0 + ra * rb * round_trip);
  };
  const double flux = (n2 * cos2).real() / (n1 * cos_incidence);
  return {std::norm(reflect(a.r_s, b.r_s)), std::norm(reflect(a.r_p, b.r_p)),
          flux * std::norm(transmit(a.t_s, b.t_s, a.r_s, b.r_s)),
          flux * std::norm(transmit(a.t_p, b.t_p, a.r_p, b.r_p))};
}

double interface_reflectance(const LensCoating& coating, double n1, double n2, double cos_incidence,
                             double wavelength_nm) {
  const double sin2_1 = std::max(0.0, 1 - cos_incidence * cos_incidence);
  auto real_cosine = [&](double n) { return 1 - sin2_1 * (n1 / n) * (n1 / n); };  // cos²
  const double c2_2 = real_cosine(n2), c2_c = coating.coated() ? real_cosine(coating.index) : 1;
  if (c2_2 < 0 || c2_c < 0)
    return coated_interface(coating, n1, n2, cos_incidence, wavelength_nm).reflectance();
  const double cos1 = cos_incidence, cos2 = std::sqrt(c2_2);
  auto face_s = [](double na, double ca, double nb, double cb) {
    return (na * ca - nb * cb) / (na * ca + nb * cb);
  };
  auto face_p = [](double na, double ca, double nb, double cb) {
    return (nb * ca - na * cb) / (nb * ca + na * cb);
  };
  if (!coating.coated()) {
    const double rs = face_s(n1, cos1, n2, cos2), rp = face_p(n1, cos1, n2, cos2);
    return 0.5 * (rs * rs + rp * rp);
  }
  const double nc = coating.index, cos_c = std::sqrt(c2_c);
  const double cos_2delta =
      std::cos(4 * std::numbers::pi * nc * coating.thickness_nm * cos_c / wavelength_nm);
  auto airy = [&](double ra, double rb) {
    const double cross = 2 * ra * rb * cos_2delta;
    return (ra * ra + rb * rb + cross) / (1 + ra * ra * rb * rb + cross);
  };
  return 0.5 * (airy(face_s(n1, cos1, nc, cos_c), face_s(nc, cos_c, n2, cos2)) +
                airy(face_p(n1, cos1, nc, cos_c), face_p(nc, cos_c, n2, cos2)));
}

}  // namespace obscura
