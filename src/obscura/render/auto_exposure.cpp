#include "obscura/render/auto_exposure.h"

#include <cmath>
#include <variant>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

// A lens system sets its own f-number, and a thin lens given an aperture diameter derives it.
std::optional<double> fixed_f_number(const Camera& camera) {
  if (std::holds_alternative<LensSystemProjection>(camera.projection) ||
      camera.lens.aperture_diameter_mm)
    return stop_f_number(camera.f_number());  // what the exposure counts with
  return std::nullopt;
}

}  // namespace

Camera metering_camera(const Camera& camera) {
  Camera c = camera;
  c.exposure.mode = ExposureMode::radiance;
  c.exposure.compensation_ev = 0;
  return c;
}

MeteredExposure meter_for(const Camera& camera, const Image& radiance_film, MeteringMode mode,
                          double compensation_ev) {
  MeteredExposure m;
  m.mode = mode;
  m.luminance_cd_m2 = metered_luminance(radiance_film, mode);
  if (!(m.luminance_cd_m2 > 0) || !std::isfinite(m.luminance_cd_m2))
    throw Error("automatic exposure",
                "the metered luminance is " + number_text(m.luminance_cd_m2) +
                    " cd/m²: nothing lit to expose for (add light, or set the exposure)");
  m.ev100 = metered_ev100(m.luminance_cd_m2);
  m.settings = program_exposure(m.ev100 - compensation_ev, fixed_f_number(camera));
  return m;
}

void apply_exposure(Camera& camera, const ExposureSettings& s) {
  camera.exposure.mode = ExposureMode::physical;
  camera.exposure.compensation_ev = 0;
  camera.exposure.iso = s.iso;
  camera.shutter.close_s = camera.shutter.open_s + s.exposure_time_s;
  if (!fixed_f_number(camera)) camera.lens.f_number = s.f_number;
}

}  // namespace obscura
