#include "obscura/render/ground_truth_frame.h"

#include <algorithm>
#include <memory>

#include "obscura/raster/ground_truth_render.h"
#include "obscura/scene/surface_motion.h"
#include "obscura/trace/embree_scene.h"
#include "obscura/trace/ground_truth_render.h"
#include "obscura/trace/trace_scene.h"

namespace obscura {

GroundTruthBuffer render_ground_truth_frame(const Scene& scene, const Camera& camera,
                                            Renderer renderer, const raster::RenderSettings& raster,
                                            const GroundTruthTimes& times) {
  const SurfaceMotion motion(scene);
  if (renderer == Renderer::kRaster) {
    raster::RasterSettings settings = raster::rasterizer_settings(raster, true);
    settings.msaa_samples = 1;     // visibility at the pixel centre
    settings.shadow_map_size = 0;  // shading plays no part
    const raster::SceneRasterizer rasterizer(scene, settings);
    return raster::render_ground_truth(rasterizer, motion, camera, times);
  }
  // Motion compiled over an interval holding both times (which may lie outside the shutter).
  Shutter interval{.open_s = std::min({times.first_s, times.second_s, camera.shutter.open_s}),
                   .close_s = std::max({times.first_s, times.second_s, camera.shutter.close_s})};
  TraceSceneOptions trace_options;
  trace_options.shutter = interval;
  const TraceScene trace(scene, std::make_shared<EmbreeDevice>(), trace_options);
  return render_ground_truth(trace, motion, camera, times);
}

}  // namespace obscura
