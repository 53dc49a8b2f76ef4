#include "obscura/color/blackbody_spectrum.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "obscura/color/spectral.h"
#include "obscura/color/spectral_working_space.h"
#include "obscura/math/error.h"

namespace obscura {

BlackbodySpectrum::BlackbodySpectrum(float kelvin) : kelvin_(kelvin) {
  if (!std::isfinite(kelvin) || kelvin <= 0)
    throw Error("temperature",
                "expected a positive number of kelvin; got " + std::to_string(kelvin));
  Vec3d xyz = spectrum_to_xyz([&](double nm) { return planck_radiance(nm, kelvin); });
  if (!(xyz[1] > 0) || !std::isfinite(xyz[1]))
    throw Error("temperature",
                "a blackbody at " + std::to_string(kelvin) + " K emits no visible light to render");
  scale_ = 1 / xyz[1];
  Vec3d rgb = working_rgb_from_xyz() * Vec3d{xyz[0] * scale_, 1, xyz[2] * scale_};
  rgb_ = {float(std::max(rgb[0], 0.0)), float(std::max(rgb[1], 0.0)), float(std::max(rgb[2], 0.0))};
}

float BlackbodySpectrum::operator()(float nm) const {
  return float(planck_radiance(nm, kelvin_) * scale_);
}

}  // namespace obscura
