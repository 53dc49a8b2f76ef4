#include "obscura/scene/ground_truth.h"

namespace obscura {

GroundTruthTimes default_ground_truth_times(const Camera& camera) {
  return {camera.shutter.open_s, camera.shutter.close_s};
}

double optical_axis_depth(const Camera& camera, Point3d world, double time_s) {
  // Camera space looks down −Z.
  return -inverse(camera.world_from_camera.at(time_s))(world).z;
}

std::optional<Vector2d> optical_flow(const Camera& camera, Point2d film_point, Point3d world_then,
                                     double then_s) {
  const std::optional<FilmProjection> then = camera.project(world_then, then_s);
  if (!then) return std::nullopt;
  return Vector2d(then->film_point.x - film_point.x, then->film_point.y - film_point.y);
}

}  // namespace obscura
