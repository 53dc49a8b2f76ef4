// The perspective (pinhole) projection, described as a photographer would: a lens of focal
// length f in front of a sensor. The field of view across a sensor dimension s is
//   FOV = 2·atan(s / (2·f)).
// Which sensor dimension the image fills is the sensor fit, with Blender's rules (see
// film_size_mm). A field of view given directly (glTF's yfov) is stored as the focal length that
// gives it on the fitted sensor dimension, so both descriptions land on the same numbers.
#pragma once

#include "obscura/math/vector.h"

namespace obscura {

// Blender's sensor fit: which image dimension the sensor size applies to.
//   automatic:  sensor_width_mm spans the larger image dimension (Blender's AUTO)
//   horizontal: sensor_width_mm spans the image width
//   vertical:   sensor_height_mm spans the image height
enum class SensorFit { automatic, horizontal, vertical };

struct Perspective {
  double focal_length_mm = 50;   // > 0
  double sensor_width_mm = 36;   // > 0 (full frame)
  double sensor_height_mm = 24;  // > 0
  SensorFit sensor_fit = SensorFit::automatic;
  // Lens shift as Blender's shift_x/shift_y: in units of the fitted film dimension, +x moves the
  // view right, +y up (the film window slides; the optical axis stays put, as a tilt-shift lens).
  Vector2d lens_shift;

  // A vertical (horizontal) field of view in degrees, in (0, 180), on a sensor of the given
  // height (width); the sensor fit becomes vertical (horizontal) so the angle is kept exactly at
  // any image aspect. Throws obscura::Error naming the value when out of range.
  static Perspective from_vertical_fov_degrees(double fov_degrees, double sensor_height_mm = 24);
  static Perspective from_horizontal_fov_degrees(double fov_degrees, double sensor_width_mm = 36);
};

// FOV = 2·atan(s / (2·f)), in degrees.
double fov_degrees(double sensor_mm, double focal_length_mm);
// The focal length giving `fov_degrees` across `sensor_mm`: f = s / (2·tan(FOV/2)).
double focal_length_mm_for_fov(double fov_degrees, double sensor_mm);

// The part of the sensor the image covers, in mm (width, height), for an image whose physical
// aspect ratio (width·pixel_aspect / height) is `image_aspect`, under the sensor fit.
Vector2d film_size_mm(const Perspective& p, double image_aspect);
// The film dimension lens shift is measured in: the one the sensor size was fitted to.
double fitted_film_dimension_mm(const Perspective& p, double image_aspect);

// Throws obscura::Error naming the first invalid parameter and its value.
void validate(const Perspective& p);

}  // namespace obscura
