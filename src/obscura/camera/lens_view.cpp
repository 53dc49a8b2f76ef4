#include "obscura/camera/lens_view.h"

#include <cmath>

namespace obscura {

LensView lens_view(const Camera& camera, Point2d lens_sample, double time_s) {
  Matrix4 projection = camera.projection_matrix();  // throws for spherical cameras
  Transform world_from_camera = camera.world_from_camera.at(time_s);
  if (!camera.lens.depth_of_field)
    return {world_from_camera.inverse_matrix(), projection, world_from_camera(Point3d(0, 0, 0)),
            Point2d(0, 0)};

  // The lens point, as generate_ray places it.
  Point2d unit = sample_aperture(camera.lens.aperture, lens_sample);
  double radius = camera.lens_radius_m();
  Point2d lens(radius * unit.x, radius * unit.y);

  // The eye moves to L: camera_from_world followed by a translation by −L.
  Matrix4 view =
      Transform::translate({-lens.x, -lens.y, 0}).matrix() * world_from_camera.inverse_matrix();

  // The window shifts by −L/S_f. In glFrustum's matrix the window enters only through the
  // scale s = 2/(max − min), unchanged by a shift, and the offset o = (max + min)/(max − min),
  // which a shift δ changes by 2δ/(max − min) = s·δ.
  double s_f = camera.lens.focus_distance_m;
  double shift_x = std::isinf(s_f) ? 0.0 : -lens.x / s_f;
  double shift_y = std::isinf(s_f) ? 0.0 : -lens.y / s_f;
  projection[0][2] += projection[0][0] * shift_x;
  projection[1][2] += projection[1][1] * shift_y;

  return {view, projection, world_from_camera(Point3d(lens.x, lens.y, 0)), lens};
}

}  // namespace obscura
