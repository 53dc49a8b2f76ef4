// Camera rays of the most common camera, made in single precision: a perspective pinhole (no depth
// of field) that does not move during the shutter. The tracer's render loop makes one per sample;
// PreparedCamera::generate_ray answers the same question for every camera in double precision
// (bit for bit as Camera does), which cost as much per sample as the rest of an escaping camera
// path. The directions agree with it to float rounding (about 1e-7 relative), far below what a
// pixel's samples resolve.
#pragma once

#include <cmath>
#include <optional>
#include <variant>

#include "obscura/camera/camera.h"
#include "obscura/math/ray.h"

namespace obscura {

class PinholeRays {
 public:
  // Rays for `camera` when it is such a pinhole; nothing otherwise.
  static std::optional<PinholeRays> of(const Camera& camera) {
    if (!std::holds_alternative<Perspective>(camera.projection) || camera.lens.depth_of_field ||
        camera.lens.vignetting.any() || camera.world_from_camera.is_animated())
      return std::nullopt;
    return PinholeRays(camera);
  }

  // The ray through raster point `film_point` at time `time_s`: unit direction, t from the near
  // to the far clipping plane (planes of constant depth, as Camera's).
  Ray generate(Point2d film_point, double time_s) const {
    // The window point (x, y) at depth 1 in front of the camera: the unnormalized direction.
    auto x = float(x_min_ + film_point.x * x_per_px_);
    auto y = float(y_max_ - film_point.y * y_per_px_);
    Vector3f d(r_[0][0] * x + r_[0][1] * y - r_[0][2], r_[1][0] * x + r_[1][1] * y - r_[1][2],
               r_[2][0] * x + r_[2][1] * y - r_[2][2]);
    float length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    Ray ray;
    ray.origin = origin_;
    ray.direction = d * (1 / length);
    // Depth 1 lies at t = length (world units): the clipping planes scale with it.
    ray.t_min = near_ * length;
    ray.t_max = far_ * length;
    ray.time = float(time_s);
    return ray;
  }

 private:
  explicit PinholeRays(const Camera& camera) {
    ScreenWindow w = camera.screen_window();
    x_min_ = w.x_min;
    y_max_ = w.y_max;
    x_per_px_ = (w.x_max - w.x_min) / camera.film.width_px;
    y_per_px_ = (w.y_max - w.y_min) / camera.film.height_px;
    const Transform& world = camera.world_from_camera.keys().front().transform;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r_[i][j] = float(world.matrix().m[i][j]);
    origin_ = Point3f(world(Point3d(0, 0, 0)));
    near_ = float(camera.near_m);
    far_ = float(camera.far_m);
  }

  double x_min_ = 0, y_max_ = 0, x_per_px_ = 0, y_per_px_ = 0;
  float r_[3][3] = {};  // world_from_camera's linear part
  Point3f origin_;
  float near_ = 0, far_ = 0;
};

}  // namespace obscura
