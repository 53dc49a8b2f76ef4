#include "obscura/io/camera_calibration.h"

#include <charconv>
#include <cmath>

#include "obscura/camera/intrinsics.h"
#include "obscura/camera/lens_system_fit.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"
#include "obscura/math/value_limits.h"

namespace obscura {

namespace {

// The largest image side a calibration may give (the CLI's limit on --width and --height).
constexpr int kMaxCalibrationSidePx = 65536;

}  // namespace

CameraCalibration calibration_of(const Camera& camera) {
  if (std::holds_alternative<LensSystemProjection>(camera.projection))
    return calibration_of(fitted_lens_camera(camera, {.check_illumination = false}).camera);
  CameraCalibration out;
  CalibratedProjection& p = out.projection;
  if (auto* c = std::get_if<CalibratedProjection>(&camera.projection)) {
    p = *c;
  } else if (!std::holds_alternative<Perspective>(camera.projection)) {
    throw Error("camera '" + camera.name + "'",
                "a calibration (K and a lens model) cannot describe its " +
                    std::string(projection_name(camera.projection)) +
                    " projection; use a perspective, calibrated or lens-system camera");
  }
  p.k = intrinsics(camera);  // scaled to the film
  p.width_px = camera.film.width_px;
  p.height_px = camera.film.height_px;
  out.world_from_camera = camera.world_from_camera.at(camera.shutter.open_s);
  out.image_name = camera.name;
  return out;
}

void apply_calibration(Camera& camera, const CameraCalibration& calibration) {
  camera.projection = calibration.projection;
  camera.film.width_px = calibration.projection.width_px;
  camera.film.height_px = calibration.projection.height_px;
  camera.film.pixel_aspect = 1;  // K holds the pixel shape
  camera.lens.depth_of_field = false;
  if (calibration.world_from_camera)
    camera.world_from_camera = AnimatedTransform(*calibration.world_from_camera);
}

CvExtrinsics cv_extrinsics(const Transform& world_from_camera) {
  // OpenCV's camera frame is Obscura's with Y and Z negated: cv_from_world = F · camera_from_world.
  const auto& m = world_from_camera.inverse_matrix().m;
  CvExtrinsics e;
  for (int i = 0; i < 3; ++i) {
    double sign = i == 0 ? 1 : -1;
    for (int j = 0; j < 3; ++j) e.r[i][j] = sign * m[i][j];
    e.t[i] = sign * m[i][3];
  }
  return e;
}

Transform world_from_camera_of(const CvExtrinsics& e, const std::string& where) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(e.t[i])) throw Error(where, "the translation is not finite");
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(e.r[i][j])) throw Error(where, "the rotation is not finite");
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double dot = 0;
      for (int k = 0; k < 3; ++k) dot += e.r[i][k] * e.r[j][k];
      if (std::abs(dot - (i == j ? 1 : 0)) > 1e-6)
        throw Error(where, "the rotation is not orthonormal (rows " + std::to_string(i) + " and " +
                               std::to_string(j) + " have dot product " + number_text(dot) + ")");
    }
  const auto& r = e.r;
  double det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
               r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
               r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
  if (det < 0) throw Error(where, "the rotation is a reflection (determinant −1)");
  // camera_from_world (Obscura) = F · [R | t]; its inverse is [Rᵀ F | −Rᵀ t] since F = F⁻¹.
  Matrix4 camera_from_world = Matrix4::identity(), world_from_camera = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    double sign = i == 0 ? 1 : -1;
    for (int j = 0; j < 3; ++j) {
      camera_from_world.m[i][j] = sign * r[i][j];
      world_from_camera.m[j][i] = sign * r[i][j];
    }
    camera_from_world.m[i][3] = sign * e.t[i];
  }
  for (int j = 0; j < 3; ++j) {
    double x = 0;
    for (int i = 0; i < 3; ++i) x -= r[i][j] * e.t[i];
    world_from_camera.m[j][3] = x;
    // Camera::validate refuses it too, but here the message names the file and line.
    if (!(std::abs(x) <= kMaxWorldCoordinateM))
      throw Error(where, "the camera position " + world_coordinate_message(x));
  }
  return Transform(world_from_camera, camera_from_world);
}

void validate_calibration(const CameraCalibration& c, const std::string& where) {
  const CalibratedProjection& p = c.projection;
  if (p.width_px < 1 || p.width_px > kMaxCalibrationSidePx || p.height_px < 1 ||
      p.height_px > kMaxCalibrationSidePx)
    throw Error(where, "the image size must be from 1 to " + std::to_string(kMaxCalibrationSidePx) +
                           " pixels a side; got " + std::to_string(p.width_px) + "x" +
                           std::to_string(p.height_px));
  try {
    validate(p);
  } catch (const Error& e) {
    throw Error(where, e.what());
  }
}

std::string exact_number(double value) {
  if (value == 0) return "0";  // not "-0"
  char buffer[40];
  auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)error;  // 40 characters hold any double
  return std::string(buffer, end);
}

}  // namespace obscura
