#include "obscura/camera/perspective.h"

#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

constexpr double kDegreesPerRadian = 180 / std::numbers::pi;

void check_fov(const char* name, double fov) {
  if (!(fov > 0 && fov < 180))
    throw Error(std::string("camera.") + name,
                "must be in (0, 180) degrees; got " + number_text(fov));
}

void check_positive(const char* name, double value) {
  if (!(value > 0) || !std::isfinite(value))
    throw Error(std::string("camera.") + name, "must be positive; got " + number_text(value));
}

bool fits_horizontally(const Perspective& p, double image_aspect) {
  switch (p.sensor_fit) {
    case SensorFit::horizontal:
      return true;
    case SensorFit::vertical:
      return false;
    case SensorFit::automatic:
      return image_aspect >= 1;
  }
  return true;
}

}  // namespace

Perspective Perspective::from_vertical_fov_degrees(double fov, double sensor_height_mm) {
  check_fov("vertical_fov_degrees", fov);
  check_positive("sensor_height_mm", sensor_height_mm);
  Perspective p;
  p.sensor_height_mm = sensor_height_mm;
  p.sensor_width_mm = sensor_height_mm * 1.5;
  p.sensor_fit = SensorFit::vertical;
  p.focal_length_mm = focal_length_mm_for_fov(fov, sensor_height_mm);
  return p;
}

Perspective Perspective::from_horizontal_fov_degrees(double fov, double sensor_width_mm) {
  check_fov("horizontal_fov_degrees", fov);
  check_positive("sensor_width_mm", sensor_width_mm);
  Perspective p;
  p.sensor_width_mm = sensor_width_mm;
  p.sensor_height_mm = sensor_width_mm / 1.5;
  p.sensor_fit = SensorFit::horizontal;
  p.focal_length_mm = focal_length_mm_for_fov(fov, sensor_width_mm);
  return p;
}

double fov_degrees(double sensor_mm, double focal_length_mm) {
  return 2 * std::atan(sensor_mm / (2 * focal_length_mm)) * kDegreesPerRadian;
}

double focal_length_mm_for_fov(double fov, double sensor_mm) {
  return sensor_mm / (2 * std::tan(fov / (2 * kDegreesPerRadian)));
}

Vector2d film_size_mm(const Perspective& p, double image_aspect) {
  switch (p.sensor_fit) {
    case SensorFit::horizontal:
      return {p.sensor_width_mm, p.sensor_width_mm / image_aspect};
    case SensorFit::vertical:
      return {p.sensor_height_mm * image_aspect, p.sensor_height_mm};
    case SensorFit::automatic:
      if (image_aspect >= 1) return {p.sensor_width_mm, p.sensor_width_mm / image_aspect};
      return {p.sensor_width_mm * image_aspect, p.sensor_width_mm};
  }
  return {};
}

double fitted_film_dimension_mm(const Perspective& p, double image_aspect) {
  Vector2d size = film_size_mm(p, image_aspect);
  return fits_horizontally(p, image_aspect) ? size.x : size.y;
}

void validate(const Perspective& p) {
  check_positive("focal_length_mm", p.focal_length_mm);
  check_positive("sensor_width_mm", p.sensor_width_mm);
  check_positive("sensor_height_mm", p.sensor_height_mm);
  if (!std::isfinite(p.lens_shift.x) || !std::isfinite(p.lens_shift.y))
    throw Error("camera.lens_shift", "must be finite");
}

}  // namespace obscura
