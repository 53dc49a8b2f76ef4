// REYES's ground truth (film/ground_truth_buffer.h): which scene triangle each pixel centre sees,
// found by REYES's own hider (one sample at the pixel centre, through the lens centre, at each of
// the two times), and the exact surface there computed from that triangle as the scene defines it:
// its plane met by the camera's ray, its interpolated normal, its motion for the optical flow.
#pragma once

#include <atomic>

#include "obscura/camera/camera.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/reyes/reyes_scene.h"
#include "obscura/reyes/reyes_settings.h"
#include "obscura/scene/ground_truth.h"

namespace obscura::reyes {

// Throws obscura::Error for a camera REYES gives no exact ground truth of: other projections
// than perspective and orthographic, and rolling shutters (a pixel's own time).
void check_ground_truth_camera(const Camera& camera);

// `settings`' shading rate, grid and bucket size and eye splits dice the surfaces; its pixel
// samples do not apply (one at each pixel centre).
GroundTruthBuffer render_ground_truth(const ReyesScene& scene, const Camera& camera,
                                      const ReyesSettings& settings, const GroundTruthTimes& times,
                                      const std::atomic<bool>* cancel);

}  // namespace obscura::reyes
