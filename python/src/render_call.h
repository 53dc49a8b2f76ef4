// The one place the Python module calls a renderer. render() (render.cpp) deals with Python —
// arguments, the GIL, Ctrl-C, progress — and hands this a plain request.
#pragma once
#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "obscura/film/aov_buffers.h"
#include "obscura/film/image.h"
#include "obscura/film/tiles.h"
#include "obscura/render/frame_request.h"
#include "obscura/render/render_session.h"
#include "obscura/scene/scene.h"

namespace obscura::python {

struct RenderRequest {
  std::string renderer = "path";  // path | whitted | direct | raster | reyes
  // What the frame is beyond the camera, each given or not (render/frame_request.h): samples,
  // seed, spectral, glare, flare; the scene file's render block fills in the rest.
  FrameRequest frame;
  std::string sampler = "sobol";  // sobol | independent
  int max_depth = 0;              // 0: the integrator's default
  double time_limit_s = 0;        // 0: none
  bool aovs = false;
  // The rasterizer's options, as `obscura render --renderer raster` names them.
  int msaa = 1;                           // 1, 4 or 8
  std::string shading = "phong";          // flat | gouraud | phong | blinn-phong
  bool cull = false, wireframe = false;   // back-face culling; edges over the image
  int shadow_map = 1024;                  // texels per side, 0: no shadows
  std::string raster_dof = "accumulate";  // off | accumulate | post
  int raster_samples = 32;                // frames accumulated for depth of field, motion blur
};

struct RenderOutcome {
  Image image;                     // linear RGB, the camera's crop size
  std::optional<AovBuffers> aovs;  // when asked for (the rasterizer's have no albedo)
  double seconds = 0, rays = 0;
  int done = 0, requested = 0;  // samples per pixel (tracer) or frames (rasterizer)
  bool cancelled = false, time_limited = false;
  std::vector<std::string> warnings;
};

// The library's settings for `request` over the scene file's render settings. Throws
// obscura::Error for an unknown renderer or sampler and out-of-range values.
FrameSettings frame_settings(const RenderRequest& request, const SceneRenderSettings& scene,
                             const std::atomic<bool>* cancel);

// Renders `camera` (null: the scene's own camera) over `scene`. Throws obscura::Error for an
// unknown renderer or sampler and for what the renderer rejects. `cancel` (set from another thread)
// stops the render early; the outcome then holds the image so far.
RenderOutcome render_request(const Scene& scene, const Camera* camera, const RenderRequest& request,
                             const std::atomic<bool>* cancel, const ProgressCallback& progress);
// The same through `session` (over its own scene), which keeps what it compiled for the next.
RenderOutcome render_request(RenderSession& session, const Camera* camera,
                             const RenderRequest& request, const std::atomic<bool>* cancel,
                             const ProgressCallback& progress);

}  // namespace obscura::python
