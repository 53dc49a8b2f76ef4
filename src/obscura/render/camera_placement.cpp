#include "obscura/render/camera_placement.h"

#include <cmath>

#include "obscura/camera/frames.h"
#include "obscura/math/number_list.h"
#include "obscura/math/number_text.h"
#include "obscura/math/request_error.h"

namespace obscura {

namespace {

std::string text_of(Vector3d v) {
  return "(" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + ")";
}
std::string text_of(Point3d p) {
  return text_of(Vector3d(p.x, p.y, p.z));
}

bool finite(Vector3d v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The sine of the angle between two unit vectors under which they count as parallel: 1e-6 rad,
// far below any intended view and far above rounding.
constexpr double kParallelSine = 1e-6;

}  // namespace

Vector3d parse_placement_vector(const std::string& text, const std::string& option) {
  std::vector<double> v = parse_list(text, ',', 3, option, "X,Y,Z (three finite numbers)");
  return {v[0], v[1], v[2]};
}

Transform look_at_pose(Point3d eye, Point3d target, Vector3d up, const std::string& where) {
  const Vector3d view = target - eye;
  if (!finite(Vector3d(eye.x, eye.y, eye.z)) || !finite(Vector3d(target.x, target.y, target.z)) ||
      !finite(up))
    throw RequestError(where + ": the position, look-at point and up must be finite");
  const double distance = length(view);
  if (!(distance > 1e-9 * std::max(1.0, length(Vector3d(eye.x, eye.y, eye.z)))))
    throw RequestError(where + ": the look-at point " + text_of(target) +
                       " is the camera's position: the view has no direction");
  const double up_length = length(up);
  if (!(up_length > 0)) throw RequestError(where + ": the up direction has zero length");
  if (length(cross(view / distance, up / up_length)) < kParallelSine)
    throw RequestError(where + ": the up direction " + text_of(up) +
                       " is parallel to the view direction " + text_of(view / distance) +
                       ": the image's roll is undefined");
  return world_from_camera_look_at(eye, target, up / up_length);
}

Transform placed_pose(const Transform& world_from_camera, const CameraPlacement& placement) {
  const Point3d old_position = world_from_camera(Point3d(0, 0, 0));
  const Vector3d old_forward = normalize(world_from_camera(Vector3d(0, 0, -1)));
  const Vector3d old_up = normalize(world_from_camera(Vector3d(0, 1, 0)));
  if (placement.position &&
      !finite(Vector3d(placement.position->x, placement.position->y, placement.position->z)))
    throw RequestError("--position must be finite; got " + text_of(*placement.position));
  const Point3d eye = placement.position.value_or(old_position);
  std::string where = placement.look_at ? "--look-at" : "--up";
  if (placement.look_at) {
    Vector3d up = placement.up.value_or(Vector3d(0, 1, 0));
    if (!placement.up) {
      // World +Y unless the view runs along it; then the camera's own up, then −Z.
      const Vector3d view = *placement.look_at - eye;
      const double d = length(view);
      if (d > 0 && length(cross(view / d, up)) < kParallelSine) {
        up = old_up;
        if (length(cross(view / d, up)) < kParallelSine) up = Vector3d(0, 0, -1);
      }
    }
    return look_at_pose(eye, *placement.look_at, up, where);
  }
  if (placement.up) return look_at_pose(eye, eye + old_forward, *placement.up, where);
  // A position alone: the orientation kept, the centre moved.
  return Transform::translate(eye - old_position) * world_from_camera;
}

}  // namespace obscura
