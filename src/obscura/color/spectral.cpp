#include "obscura/color/spectral.h"

#include <cmath>
#include <string>

#include "obscura/color/cie_tables.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

void check_wavelength(double nm) {
  if (!std::isfinite(nm) || nm <= 0)
    throw Error("wavelength",
                "expected a positive number of nanometres; got " + std::to_string(nm));
}

// Linear interpolation of a table column; 0 outside the table.
double sample(const SpectralTable& t, int column, double nm) {
  double row = nm - t.first_nm;
  if (row < 0 || row > t.rows() - 1) return 0;
  int i = int(row);
  double f = row - i;
  if (i + 1 >= t.rows()) return t.at(i, column);
  return t.at(i, column) * (1 - f) + t.at(i + 1, column) * f;
}

Vec3d integrate(const SpectralTable& t, const std::function<double(double)>& spd) {
  Vec3d sum{0, 0, 0};
  for (int row = 0; row < t.rows(); ++row) {
    double s = spd(t.first_nm + row);
    for (int c = 0; c < 3; ++c) sum[c] += s * t.at(row, c);
  }
  return sum;
}

}  // namespace

Vec3d cmf_xyz(double nm) {
  check_wavelength(nm);
  const SpectralTable& t = cie1931_cmf();
  return {sample(t, 0, nm), sample(t, 1, nm), sample(t, 2, nm)};
}

Vec3d cone_lms(double nm) {
  check_wavelength(nm);
  const SpectralTable& t = stockman_sharpe_lms();
  return {sample(t, 0, nm), sample(t, 1, nm), sample(t, 2, nm)};
}

Vec3d spectrum_to_xyz(const std::function<double(double)>& spd) {
  return integrate(cie1931_cmf(), spd);
}

Vec3d spectrum_to_lms(const std::function<double(double)>& spd) {
  return integrate(stockman_sharpe_lms(), spd);
}

double d65_spd(double nm) {
  check_wavelength(nm);
  return sample(cie_d65_spd(), 0, nm);
}

double planck_radiance(double nm, double kelvin) {
  check_wavelength(nm);
  if (!std::isfinite(kelvin) || kelvin <= 0)
    throw Error("temperature",
                "expected a positive number of kelvin; got " + std::to_string(kelvin));
  constexpr double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;  // SI 2019, exact
  double lambda = nm * 1e-9;
  double radiance_per_m =
      2 * h * c * c / std::pow(lambda, 5) / std::expm1(h * c / (lambda * k * kelvin));
  return radiance_per_m * 1e-9;
}

Vec3d blackbody_xyz(double kelvin) {
  if (!std::isfinite(kelvin) || kelvin <= 0)
    throw Error("temperature",
                "expected a positive number of kelvin; got " + std::to_string(kelvin));
  constexpr double c2 = 1.4388e-2;  // m·K; c₁ cancels in the normalisation
  Vec3d xyz = spectrum_to_xyz([&](double nm) {
    double lambda = nm * 1e-9;
    return 1 / (std::pow(lambda, 5) * std::expm1(c2 / (lambda * kelvin)));
  });
  double y = xyz[1];
  if (!(y > 0))
    throw Error("temperature",
                "blackbody at " + std::to_string(kelvin) + " K emits no visible light to measure");
  return {xyz[0] / y, 1, xyz[2] / y};
}

Chromaticity chromaticity_of(const Vec3d& xyz) {
  double sum = xyz[0] + xyz[1] + xyz[2];
  if (sum == 0) return {0, 0};
  return {xyz[0] / sum, xyz[1] / sum};
}

}  // namespace obscura
