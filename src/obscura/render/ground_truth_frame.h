// The ground truth of a frame (depth, position, normals, ids, optical flow; film/
// ground_truth_buffer.h) by either renderer's visibility: one ray per pixel centre from the
// tracer, or the rasterizer's z-buffer at the pixel centre.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/raster/render.h"
#include "obscura/render/renderer.h"
#include "obscura/scene/ground_truth.h"
#include "obscura/scene/scene.h"

namespace obscura {

// `raster` gives the rasterizer's culling and shading settings (its MSAA and shadows play no
// part: visibility is taken at the pixel centre). Throws obscura::Error for a camera the
// renderer cannot give the ground truth of.
GroundTruthBuffer render_ground_truth_frame(const Scene& scene, const Camera& camera,
                                            Renderer renderer, const raster::RenderSettings& raster,
                                            const GroundTruthTimes& times);

}  // namespace obscura
