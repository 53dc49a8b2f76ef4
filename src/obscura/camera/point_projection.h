// Camera::project and Camera::unproject over arrays of points at one time (what Python's
// Camera.project / Camera.unproject call): the same doubles, point for point, with what does not
// change from point to point (the pose at that time, the screen window) computed once and the
// perspective and orthographic cameras in a loop of their own. Runs in parallel over chunks;
// each point's result depends only on that point, so not on the thread count.
#pragma once
#include <cstddef>

#include "obscura/camera/camera.h"

namespace obscura {

// world: n points (x, y, z); film: n raster points (x, y); depth: n depths. Points the camera does
// not see get NaN in both outputs. Returns whether every coordinate was finite (checked here, in
// the parallel loop, rather than in a serial pass before it; a non-finite point gets NaN).
template <typename T>
bool project_points(const Camera& camera, const T* world, size_t n, double time_s, double* film,
                    double* depth);

// film: n raster points, depth: n depths; world: n points, NaN where the camera sees nothing.
template <typename T>
void unproject_points(const Camera& camera, const T* film, const T* depth, size_t n, double time_s,
                      double* world);

}  // namespace obscura
