#include "obscura/render/calibrated_camera_request.h"

#include <cmath>

#include "obscura/camera/intrinsics.h"
#include "obscura/io/calibration_file.h"
#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/error.h"
#include "obscura/math/number_list.h"
#include "obscura/math/request_error.h"

namespace obscura {

namespace {

// The largest image side a calibration may be given for (the command line's --width limit).
constexpr int kMaxCalibrationSidePx = 65536;

Intrinsics parse_intrinsics(const std::string& text) {
  std::vector<double> v = parse_list(text, ',', 4, 5, "--intrinsics",
                                     "fx,fy,cx,cy[,skew] in pixels (800,800,319.5,239.5)");
  if (!(v[0] > 0) || !(v[1] > 0))
    throw RequestError("--intrinsics: fx and fy must be positive; got '" + text + "'");
  return {.fx = v[0], .fy = v[1], .cx = v[2], .cy = v[3], .skew = v.size() == 5 ? v[4] : 0};
}

std::pair<int, int> parse_size(const std::string& text) {
  std::string lower = text;
  for (char& c : lower)
    if (c == 'X') c = 'x';
  std::vector<double> v =
      parse_list(lower, 'x', 2, "--calibration-size", "WxH in pixels (640x480)");
  for (double side : v)
    if (!(side >= 1 && side <= double(kMaxCalibrationSidePx) && side == std::floor(side)))
      throw RequestError("--calibration-size expects whole numbers of pixels from 1 to " +
                         std::to_string(kMaxCalibrationSidePx) + "; got '" + text + "'");
  return {int(v[0]), int(v[1])};
}

LensModel parse_distortion(const std::string& text) {
  size_t colon = text.find(':');
  std::string name = text.substr(0, colon);
  std::vector<double> coefficients;
  if (colon != std::string::npos)
    coefficients = parse_list(text.substr(colon + 1), ',', 1, 14, "--distortion",
                              "MODEL[:c1,c2,...] (opencv:-0.28,0.07,0.001,0.0002,0)");
  try {
    return lens_model_from_coefficients(name, coefficients);
  } catch (const Error& e) {
    throw RequestError(std::string("--distortion: ") + e.what() + " (got '" + text + "')");
  }
}

// The calibrated projection the camera starts from: its own, or a perspective camera's framing
// as K (in the film's pixels).
CalibratedProjection calibrated_start(const Camera& camera, const CameraRequest& o) {
  if (auto* c = std::get_if<CalibratedProjection>(&camera.projection)) return *c;
  CalibratedProjection c;
  if (std::holds_alternative<Perspective>(camera.projection)) {
    c.k = intrinsics(camera);
    return c;
  }
  if (!o.intrinsics)
    throw RequestError("a calibrated camera made from a " +
                       std::string(projection_name(camera.projection)) +
                       " camera needs --intrinsics fx,fy,cx,cy (or --calibration FILE)");
  return c;
}

}  // namespace

void apply_calibration_file(Camera& camera, const CameraRequest& o) {
  if (!o.calibration) {
    if (o.calibration_image)
      throw RequestError("--calibration-image '" + *o.calibration_image +
                         "' needs --calibration FILE");
    return;
  }
  apply_calibration(camera,
                    read_calibration_file(*o.calibration, o.calibration_image.value_or("")));
}

void apply_calibrated_overrides(Camera& camera, const CameraRequest& o) {
  bool calibrated_asked = (o.projection && *o.projection == "calibrated") || o.intrinsics ||
                          o.calibration_size || o.distortion || o.max_field_angle_degrees;
  if (!calibrated_asked) return;
  CalibratedProjection c = calibrated_start(camera, o);
  if (o.intrinsics) {
    c.k = parse_intrinsics(*o.intrinsics);
    c.width_px = c.height_px = 0;  // the film's pixels, unless --calibration-size
  }
  if (o.calibration_size) std::tie(c.width_px, c.height_px) = parse_size(*o.calibration_size);
  if (o.distortion) c.lens = parse_distortion(*o.distortion);
  if (o.max_field_angle_degrees) c.max_field_angle_degrees = *o.max_field_angle_degrees;
  camera.projection = c;
  camera.lens.depth_of_field = false;  // calibrated lens models are pinholes
}

}  // namespace obscura
