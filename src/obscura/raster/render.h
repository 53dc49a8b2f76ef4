// The rasterizer's one entry point, beside the tracer's obscura::render (trace/render.h): a scene
// seen by a camera into a film, with the camera's effects composed as the scene needs them —
// depth of field by accumulating jittered lens views or as a z-buffer post-process, motion blur
// by accumulating shutter times whenever the shutter is open and something moves, lens-warped
// views for cameras without a projection matrix, bands for a rolling shutter (see
// docs/raster-effects.md).
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/film/image.h"
#include "obscura/film/tiles.h"
#include "obscura/film/work_share.h"
#include "obscura/raster/render_settings.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/scene/scene.h"

namespace obscura::raster {

class RasterizerCache;  // rasterizer_cache.h

struct RenderStats {
  double seconds = 0;  // compiling the scene and drawing the frame(s)
  int frames = 0;      // frames drawn (accumulated)
  int frames_requested = 0;
  bool cancelled = false;
  bool time_limited = false;
  std::vector<std::string> warnings;
  // Post-process depth of field: what blurs the whole frame once it is assembled, which
  // render/frame_finish.h does for every renderer and every way a frame is split (the film
  // render leaves is sharp).
  std::optional<PostDepthOfFieldInputs> post_dof;
};

// The SceneRasterizer's settings for `settings` (with AOV targets if `aovs`).
RasterSettings rasterizer_settings(const RenderSettings& settings, bool aovs);

// Whether an instance moves or a mesh deforms over the shutter.
bool scene_moves(const Scene& scene);

// Whether the render accumulates frames or post-processes (rather than drawing one sharp frame
// at mid-shutter): the camera has depth of field (and the method is not off), or the shutter is
// open while the camera or an instance moves. Never for cameras drawn through lens views or band
// by band (drawn sharp; render warns when something moves).
bool wants_effects(const Scene& scene, const Camera& camera, const RenderSettings& settings);

// Renders `camera` over `scene` into `film` (the camera's crop size) and, if given, `aovs` (the
// same size): the normal, the distance along the pixel centre's ray and the instance id of the
// frame nearest mid-shutter. The rasterizer has no albedo: `aovs` is replaced by buffers without
// one. With `prepared` (a cache over the same scene), the scene's preparation is taken from it
// and kept there for the next frame. Throws obscura::Error for invalid settings or a film of
// another size.
RenderStats render(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                   Film& film, AovBuffers* aovs = nullptr, const ProgressCallback& progress = {},
                   RasterizerCache* prepared = nullptr);

}  // namespace obscura::raster
