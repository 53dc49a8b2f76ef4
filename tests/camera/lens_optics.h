// The tests' own first-order optics of a lens prescription: paraxial ray-transfer (ABCD) matrices
// acting on (height y, reduced angle n·u), written here independently of the lens system's exact
// ray tracing. Refraction at a surface of radius R from index n into n' is
//   [[1, 0], [−(n' − n) / R, 1]],
// transfer over a thickness t in index n is [[1, t / n], [0, 1]]. For the system matrix
// [[A, B], [C, D]] from the front surface to the rear one, a ray parallel to the axis at height 1
// leaves at height A with reduced angle C: EFL = −1 / C and BFD = −A / C.
#pragma once

#include <array>
#include <cmath>
#include <functional>

#include "obscura/camera/lens_prescription.h"

namespace obscura::test {

using Matrix2 = std::array<std::array<double, 2>, 2>;

inline Matrix2 multiply(const Matrix2& a, const Matrix2& b) {
  Matrix2 m{};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j];
  return m;
}

struct ParaxialOptics {
  double efl_mm = 0, bfd_mm = 0, entrance_pupil_mm = 0;
  double f_number() const { return efl_mm / entrance_pupil_mm; }
};

// `index_of(n_d, V_d)` gives a medium's index at the wavelength of interest (n_d itself at d).
inline ParaxialOptics paraxial_optics(
    const LensPrescription& p,
    const std::function<double(double, double)>& index_of = [](double n, double) { return n; }) {
  Matrix2 system{{{1, 0}, {0, 1}}};
  Matrix2 to_stop{};
  double stop_diameter = 0;
  double n = 1;
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    const LensSurface& s = p.surfaces[i];
    double n_after = s.n_d == 1 ? 1 : index_of(s.n_d, s.abbe_number);
    if (s.is_stop) {
      to_stop = system;
      stop_diameter = s.aperture_diameter_mm;
    }
    if (s.radius_mm != 0) system = multiply({{{1, 0}, {-(n_after - n) / s.radius_mm, 1}}}, system);
    n = n_after;
    if (i + 1 < p.surfaces.size()) system = multiply({{{1, s.thickness_mm / n}, {0, 1}}}, system);
  }
  ParaxialOptics o;
  o.efl_mm = -1 / system[1][0];
  o.bfd_mm = -system[0][0] / system[1][0];
  // The axial ray of height 1 reaches the stop at height to_stop[0][0]: the stop's image seen
  // from the scene is the stop's diameter scaled back by that.
  o.entrance_pupil_mm = stop_diameter / std::abs(to_stop[0][0]);
  return o;
}

}  // namespace obscura::test
