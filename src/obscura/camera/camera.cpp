#include "obscura/camera/camera.h"

#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

void Camera::validate() const {
  if (!(vertical_fov_degrees > 0 && vertical_fov_degrees < 180))
    throw Error("camera.vertical_fov_degrees",
                "must be in (0, 180); got " + std::to_string(vertical_fov_degrees));
  if (width <= 0 || height <= 0)
    throw Error("camera resolution",
                "must be positive; got " + std::to_string(width) + "x" + std::to_string(height));
}

Ray Camera::generate_ray(Point2f film_point) const {
  double tan_half = std::tan(vertical_fov_degrees * std::numbers::pi / 360.0);
  double aspect = double(width) / height;
  // Raster → normalized device coordinates in [−1, 1] (y up) → the image plane at z = −1.
  double ndc_x = 2.0 * film_point.x / width - 1.0;
  double ndc_y = 1.0 - 2.0 * film_point.y / height;
  Vector3d direction_camera(ndc_x * tan_half * aspect, ndc_y * tan_half, -1.0);
  Point3d origin_world = world_from_camera(Point3d(0, 0, 0));
  Vector3d direction_world = normalize(world_from_camera(direction_camera));
  Ray ray;
  ray.origin = Point3f(origin_world);
  ray.direction = Vector3f(direction_world);
  return ray;
}

}  // namespace obscura
