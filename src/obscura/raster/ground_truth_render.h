// The rasterizer's ground truth (film/ground_truth_buffer.h), for any camera the rasterizer
// draws: visibility from a frame drawn at each of the two times with one sample per pixel (at
// the pixel centre) and the id outputs on; then, per pixel, the centre ray (from the camera) met
// with the plane of the triangle the rasterizer found there, taken from the authoring scene at
// that time. So the values are exact per pixel centre, as the tracer's; only which triangle a
// pixel sees can differ from the tracer's where a triangle edge passes within the rasterizer's
// sub-pixel precision of the centre.
//
// Where the triangle cannot be trusted — alpha-blended instances (drawn sorted, so the primitive
// id is not the mesh's triangle index) or a ray parallel to the plane — the position comes from
// unprojecting the rasterizer's interpolated view depth and Ng is the rasterizer's normal; a
// plane that disagrees with the drawn depth by more than 10⁻³ relative is not trusted either.
#pragma once

#include <atomic>

#include "obscura/camera/camera.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/scene/ground_truth.h"
#include "obscura/scene/surface_motion.h"

namespace obscura::raster {

// The ground truth of the camera's crop window (pixel (0, 0) is the crop's top-left pixel).
// `rasterizer` must have aovs on and one sample per pixel, and be compiled from `motion`'s
// scene. Throws obscura::Error otherwise, and for cameras the rasterizer cannot draw.
// Throws obscura::Error, naming the tracer, for the cameras whose ground truth the rasterizer
// cannot give exactly: those without a projection matrix and rolling shutters.
void check_ground_truth_camera(const Camera& camera);

// `cancel`, once set (from another thread, a signal handler), stops the work between the two
// drawings and between rows: the rows not yet done are left empty, for the caller to throw away.
GroundTruthBuffer render_ground_truth(const SceneRasterizer& rasterizer,
                                      const SurfaceMotion& motion, const Camera& camera,
                                      const GroundTruthTimes& times,
                                      const std::atomic<bool>* cancel = nullptr);

}  // namespace obscura::raster
