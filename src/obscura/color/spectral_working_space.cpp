#include "obscura/color/spectral_working_space.h"

#include "obscura/color/primaries.h"
#include "obscura/color/spectral.h"

namespace obscura {

namespace {

double d65_luminance() {
  static const double y = spectrum_to_xyz([](double nm) { return d65_spd(nm); })[1];
  return y;
}

}  // namespace

double working_illuminant(double wavelength_nm) {
  return d65_spd(wavelength_nm) / d65_luminance();
}

const Matrix3d& working_rgb_from_xyz() {
  static const Matrix3d matrix = [] {
    Matrix3d rgb_from_xyz = xyz_from_rgb(primaries::kRec709).inverse();
    Vec3d white = rgb_from_xyz * spectrum_to_xyz(working_illuminant);
    return Matrix3d::diagonal({1 / white[0], 1 / white[1], 1 / white[2]}) * rgb_from_xyz;
  }();
  return matrix;
}

}  // namespace obscura
