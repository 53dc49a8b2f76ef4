// What both renderers share to compute ground-truth channels (film/ground_truth_buffer.h) for
// any camera projection: the two times, and the camera-side quantities of a seen point.
#pragma once

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
double optical_axis_depth(const Camera& camera, Point3d world, double time_s);

// Optical flow of a point seen through raster point `film_point` that is at `world_then` at
// time `then_s`: where the camera puts it then, minus `film_point` (pixels, x right, y down).
// Nothing when it is not on the film then (behind the camera, outside the near/far range, off
// the film, outside a fisheye's circle).
std::optional<Vector2d> optical_flow(const Camera& camera, Point2d film_point, Point3d world_then,
                                     double then_s);

}  // namespace obscura
