#include "obscura/camera/calibrated_projection.h"

#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

void validate(const CalibratedProjection& p) {
  auto finite_positive = [](const char* field, double v) {
    if (!(std::isfinite(v) && v > 0))
      throw Error(std::string("camera.intrinsics.") + field,
                  "must be a positive number of pixels; got " + number_text(v));
  };
  finite_positive("fx", p.k.fx);
  finite_positive("fy", p.k.fy);
  // A pixel 1 px off the principal point looks atan(1 / f) off axis: under a thousandth of a
  // pixel, every pixel but the centre one looks more than 89.94° away, and the frame is black.
  constexpr double kMinFocalPx = 1e-3;
  for (auto [field, f] : {std::pair{"fx", p.k.fx}, std::pair{"fy", p.k.fy}})
    if (f < kMinFocalPx)
      throw Error(std::string("camera.intrinsics.") + field,
                  "must be at least " + number_text(kMinFocalPx) +
                      " pixels (a shorter focal length images nothing); got " + number_text(f));
  for (auto [field, v] :
       {std::pair{"cx", p.k.cx}, std::pair{"cy", p.k.cy}, std::pair{"skew", p.k.skew}})
    if (!std::isfinite(v))
      throw Error(std::string("camera.intrinsics.") + field,
                  "must be a finite number; got " + number_text(v));
  if (p.width_px < 0 || p.height_px < 0 || (p.width_px == 0) != (p.height_px == 0))
    throw Error("camera.intrinsics.image_size",
                "must be both positive (the calibration's image size) or both 0 (the film's); "
                "got " +
                    number_text(p.width_px) + "x" + number_text(p.height_px));
  if (!(p.max_field_angle_degrees >= 0 && p.max_field_angle_degrees <= 180))
    throw Error("camera.lens.max_field_angle_degrees",
                "must be in (0, 180] degrees from the axis, or 0 for the model's limit; got " +
                    number_text(p.max_field_angle_degrees));
  validate(p.lens);
}

double max_field_angle_rad(const CalibratedProjection& p) {
  return p.max_field_angle_degrees * (std::numbers::pi / 180);
}

const LensMap& lens_map(const CalibratedProjection& p) {
  struct Cached {
    LensModel model;
    double max_angle = -1;
    std::optional<LensMap> map;
  };
  thread_local Cached cached;
  double max_angle = max_field_angle_rad(p);
  if (!cached.map || cached.max_angle != max_angle || !(cached.model == p.lens)) {
    cached.map.emplace(p.lens, max_angle);
    cached.model = p.lens;
    cached.max_angle = max_angle;
  }
  return *cached.map;
}

}  // namespace obscura
