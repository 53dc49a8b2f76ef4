// What both renderers share to compute ground-truth channels (film/ground_truth_buffer.h) for
// any camera projection: the two times, and the camera-side quantities of a seen point.
#pragma once

#include <functional>
#include <optional>

#include "obscura/camera/camera.h"
#include "obscura/math/vector.h"

namespace obscura {

// The reference time (depth, position, normals, ids, forward flow's start) and the second time
// (forward flow's end, backward flow's start). Default: the shutter's open and close times.
struct GroundTruthTimes {
  double first_s = 0, second_s = 0;
};

GroundTruthTimes default_ground_truth_times(const Camera& camera);

// Depth of `world` along the camera's optical axis at `time_s` (m; positive in front).
double optical_axis_depth(const PreparedCamera& camera, Point3d world, double time_s);

// Optical flow of a point seen through raster point `film_point`, whose position at any time
// `world_at` gives, to the exposure that starts at `then_s`: where the camera puts it in that
// exposure, minus `film_point` (pixels, x right, y down). With a rolling shutter the point is
// seen when the line it lands on is exposed (then_s + that line's delay), found by fixed-point
// iteration to 1e-9 px. Nothing when it is not on the film then (behind the camera, outside the
// near/far range, off the film, outside a fisheye's circle) or the iteration does not settle.
std::optional<Vector2d> optical_flow(const PreparedCamera& camera, Point2d film_point,
                                     const std::function<Point3d(double)>& world_at, double then_s);

}  // namespace obscura
