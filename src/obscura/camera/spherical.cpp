#include "obscura/camera/spherical.h"

#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {
constexpr double kPi = std::numbers::pi;
}

void validate(const Fisheye& f) {
  if (!(f.fov_degrees > 0 && f.fov_degrees <= 360))
    throw Error("camera.fisheye_fov_degrees",
                "must be in (0, 360]; got " + number_text(f.fov_degrees));
}

Vector3d equirectangular_direction(Point2d uv) {
  double longitude = 2 * kPi * (uv.x - 0.5);
  double latitude = kPi * (0.5 - uv.y);
  double c = std::cos(latitude);
  return {c * std::sin(longitude), std::sin(latitude), -c * std::cos(longitude)};
}

Point2d equirectangular_uv(Vector3d d) {
  double longitude = std::atan2(d.x, -d.z);
  double latitude = std::atan2(d.y, std::hypot(d.x, d.z));
  return {longitude / (2 * kPi) + 0.5, 0.5 - latitude / kPi};
}

std::optional<Vector3d> fisheye_direction(const Fisheye& f, Point2d centered) {
  double r = std::hypot(centered.x, centered.y);
  if (r > 1) return std::nullopt;
  double theta = r * f.fov_degrees * (kPi / 360);
  double phi = std::atan2(centered.y, centered.x);
  double s = std::sin(theta);
  return Vector3d(s * std::cos(phi), s * std::sin(phi), -std::cos(theta));
}

std::optional<Point2d> fisheye_centered(const Fisheye& f, Vector3d d) {
  double theta = std::atan2(std::hypot(d.x, d.y), -d.z);  // angle from the optical axis −Z
  double r = theta / (f.fov_degrees * (kPi / 360));
  if (r > 1) return std::nullopt;
  double phi = std::atan2(d.y, d.x);
  return Point2d(r * std::cos(phi), r * std::sin(phi));
}

}  // namespace obscura
