#include "obscura/scene/ground_truth.h"

#include <cmath>

namespace obscura {

GroundTruthTimes default_ground_truth_times(const Camera& camera) {
  return {camera.shutter.open_s, camera.shutter.close_s};
}

double optical_axis_depth(const PreparedCamera& camera, Point3d world, double time_s) {
  // Camera space looks down −Z.
  return -inverse(camera.world_from_camera(time_s))(world).z;
}

std::optional<Vector2d> optical_flow(const PreparedCamera& camera, Point2d film_point,
                                     const std::function<Point3d(double)>& world_at,
                                     double then_s) {
  const Shutter& shutter = camera.camera().shutter;
  // Start from the line the point was seen on; each step re-times the point by the line it lands
  // on. The map contracts when the image moves less than a line per line time.
  double time = then_s + camera.camera().readout_delay_s(film_point);
  std::optional<FilmProjection> then = camera.project(world_at(time), time);
  for (int i = 0; i < 50 && then && shutter.line_time_s > 0; ++i) {
    const double next = then_s + camera.camera().readout_delay_s(then->film_point);
    if (next == time) break;
    time = next;
    const Point2d before = then->film_point;
    then = camera.project(world_at(time), time);
    if (then && std::hypot(then->film_point.x - before.x, then->film_point.y - before.y) < 1e-9)
      break;
    if (i == 49) return std::nullopt;
  }
  if (!then) return std::nullopt;
  return Vector2d(then->film_point.x - film_point.x, then->film_point.y - film_point.y);
}

}  // namespace obscura
