#include "render_call.h"

#include "obscura/film/film.h"
#include "obscura/math/error.h"
#include "obscura/render/render_frame.h"

namespace obscura::python {

namespace {

SamplerType sampler_named(const std::string& name) {
  if (std::optional<SamplerType> type = parse_sampler_type(name)) return *type;
  throw Error("sampler", "expected 'sobol' or 'independent', got '" + name + "'");
}

raster::ShadingMode shading_named(const std::string& name) {
  if (std::optional<raster::ShadingMode> mode = raster::parse_shading_mode(name)) return *mode;
  throw Error("shading",
              "expected 'flat', 'gouraud', 'phong' or 'blinn-phong', got '" + name + "'");
}

raster::DepthOfFieldMethod depth_of_field_named(const std::string& name) {
  if (std::optional<raster::DepthOfFieldMethod> method = raster::parse_depth_of_field_method(name))
    return *method;
  throw Error("raster_dof", "expected 'off', 'accumulate' or 'post', got '" + name + "'");
}

}  // namespace

FrameSettings frame_settings(const RenderRequest& r, const SceneRenderSettings& scene,
                             const std::atomic<bool>* cancel) {
  std::optional<Renderer> renderer = parse_renderer(r.renderer);
  if (!renderer)
    throw Error("renderer", "expected " + renderer_names() + ", got '" + r.renderer + "'");
  const ResolvedFrameRequest frame = resolve_frame_request(r.frame, scene, *renderer);
  if (frame.samples_per_pixel <= 0 || frame.samples_per_pixel > kMaxSamplesPerPixel)
    throw Error("spp", "expected 1 to " + std::to_string(kMaxSamplesPerPixel) + ", got " +
                           std::to_string(frame.samples_per_pixel));
  if (!(r.time_limit_s >= 0))
    throw Error("time_limit", "expected seconds >= 0, got " + std::to_string(r.time_limit_s));
  FrameSettings s{.renderer = *renderer,
                  .samples_per_pixel = frame.samples_per_pixel,
                  .seed = frame.seed,
                  .sampler = sampler_named(r.sampler),
                  .max_depth = r.max_depth,
                  .spectral = frame.spectral,
                  .time_limit_s = r.time_limit_s,
                  .cancel = cancel,
                  .share = {},
                  .raster = {},
                  .glare = frame.glare,
                  .flare = frame.flare};
  s.raster.msaa_samples = r.msaa;
  s.raster.shading = shading_named(r.shading);
  s.raster.cull_back_faces = r.cull;
  s.raster.wireframe = r.wireframe;
  s.raster.shadow_map_size = r.shadow_map;
  s.raster.depth_of_field = depth_of_field_named(r.raster_dof);
  s.raster.effect_samples = r.raster_samples;
  s.reyes = frame.reyes;
  return s;
}

RenderOutcome render_request(RenderSession& session, const Camera* camera,
                             const RenderRequest& request, const std::atomic<bool>* cancel,
                             const ProgressCallback& progress) {
  const Scene& scene = session.scene();
  const FrameSettings settings = frame_settings(request, scene.render, cancel);
  const Camera& view = camera ? *camera : scene.camera;
  view.validate();
  // The session renders `view` over its scene as it is: the tracer compiles object motion over
  // view's exposure, so another camera needs no copy of the scene.

  RenderedFrame frame = session.render(view, settings, request.aovs, progress);
  RenderOutcome outcome;
  outcome.image = frame.finished();
  outcome.aovs = std::move(frame.aovs);
  const FrameStats& stats = frame.stats;
  outcome.seconds = stats.seconds;
  outcome.rays = stats.rays;
  outcome.done = stats.done;
  outcome.requested = stats.requested;
  outcome.cancelled = stats.cancelled;
  outcome.time_limited = stats.time_limited;
  outcome.warnings = scene.warnings;
  outcome.warnings.insert(outcome.warnings.end(), stats.warnings.begin(), stats.warnings.end());
  return outcome;
}

RenderOutcome render_request(const Scene& scene, const Camera* camera, const RenderRequest& request,
                             const std::atomic<bool>* cancel, const ProgressCallback& progress) {
  scene.validate();
  RenderSession session(scene);
  return render_request(session, camera, request, cancel, progress);
}

}  // namespace obscura::python
