// The ground truth of a frame (depth, position, normals, ids, optical flow; film/
// ground_truth_buffer.h) by a renderer's visibility: one ray per pixel centre from the tracer,
// the rasterizer's z-buffer at the pixel centre (RendererBackend::ground_truth).
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/render/frame_settings.h"
#include "obscura/scene/ground_truth.h"
#include "obscura/scene/scene.h"

namespace obscura {

// settings.renderer's visibility, with its settings (the rasterizer's culling; its MSAA and
// shadows play no part). Throws obscura::Error for a renderer without ground truth or a camera
// it cannot give the ground truth of. A RenderSession (render/render_session.h) renders the
// same, reusing the scene it compiled for the frame.
GroundTruthBuffer render_ground_truth_frame(const Scene& scene, const Camera& camera,
                                            const FrameSettings& settings,
                                            const GroundTruthTimes& times);

}  // namespace obscura
