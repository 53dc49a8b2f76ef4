// The tracer's ground truth (film/ground_truth_buffer.h): one ray through each pixel's centre
// and the lens centre at the first time, one more at the second for the backward flow; exact
// and deterministic for any camera projection (it asks the camera for the rays).
#pragma once

#include <atomic>

#include "obscura/camera/camera.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/scene/ground_truth.h"
#include "obscura/scene/surface_motion.h"
#include "obscura/trace/trace_scene.h"

namespace obscura {

// The ground truth of the camera's crop window (the buffer has the crop's size; pixel (0, 0) is
// the crop's top-left pixel). `scene` must be compiled for a shutter that holds both times (its
// motion is only known there); `motion` is of the same authoring scene. Throws obscura::Error
// when a time lies outside the compiled shutter. `cancel`, once set (from another thread, a signal
// handler), stops the work at the next tile: the tiles not yet started are left empty, and the
// caller, who set it, throws the buffer away.
GroundTruthBuffer render_ground_truth(const TraceScene& scene, const SurfaceMotion& motion,
                                      const Camera& camera, const GroundTruthTimes& times,
                                      const std::atomic<bool>* cancel = nullptr);

}  // namespace obscura
