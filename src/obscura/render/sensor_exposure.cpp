#include "obscura/render/sensor_exposure.h"

#include <cmath>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {
constexpr double kLensFactor = 0.65;  // ISO 12232's q (camera/exposure.cpp's calibration)
}  // namespace

SensorExposure sensor_exposure(const Camera& camera) {
  const double t = camera.shutter.duration_s();
  if (!(t > 0) || !std::isfinite(t))
    throw Error("camera.shutter",
                "a raw sensor integrates while the shutter is open; got " + number_text(t) + " s");
  const double n = stop_f_number(camera.f_number());
  if (!(n > 0) || !std::isfinite(n))
    throw Error("camera.f_number", "a raw sensor needs a positive f-number; got " + number_text(n));
  SensorExposure e;
  e.exposure_time_s = t;
  e.iso = camera.exposure.iso;
  e.lux_seconds_per_film = kLensFactor * t / (n * n * camera.exposure_scale());
  return e;
}

}  // namespace obscura
