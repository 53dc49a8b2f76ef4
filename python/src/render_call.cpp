#include "render_call.h"

#include <memory>

#include "obscura/film/film.h"
#include "obscura/math/error.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/embree_scene.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "obscura/trace/whitted.h"

namespace obscura::python {

namespace {

// Until the library has one entry point for both renderers (issue 16's render_frame), the
// module renders with the tracer's own, building what it needs as the CLI does.
std::unique_ptr<Integrator> integrator_for(const RenderRequest& r) {
  if (r.renderer == "whitted")
    return std::make_unique<WhittedIntegrator>(
        WhittedSettings{.max_depth = r.max_depth > 0 ? r.max_depth : WhittedSettings().max_depth});
  if (r.renderer == "direct") return std::make_unique<DirectLightingIntegrator>();
  if (r.renderer == "path")
    return std::make_unique<PathTracer>(PathTracerSettings{
        .max_depth = r.max_depth > 0 ? r.max_depth : PathTracerSettings().max_depth});
  if (r.renderer == "raster")
    throw Error("renderer", "'raster' is not available from Python in this build yet");
  throw Error("renderer",
              "expected 'path', 'whitted', 'direct' or 'raster', got '" + r.renderer + "'");
}

SamplerType sampler_for(const std::string& name) {
  if (name == "sobol") return SamplerType::kSobol;
  if (name == "independent") return SamplerType::kIndependent;
  throw Error("sampler", "expected 'sobol' or 'independent', got '" + name + "'");
}

}  // namespace

RenderOutcome render_request(const Scene& scene, const Camera* camera, const RenderRequest& request,
                             const std::atomic<bool>* cancel, const ProgressCallback& progress) {
  if (request.samples_per_pixel <= 0 || request.samples_per_pixel > kMaxSamplesPerPixel)
    throw Error("spp", "expected 1 to " + std::to_string(kMaxSamplesPerPixel) + ", got " +
                           std::to_string(request.samples_per_pixel));
  if (!(request.time_limit_s >= 0))
    throw Error("time_limit", "expected seconds >= 0, got " + std::to_string(request.time_limit_s));
  std::unique_ptr<Integrator> integrator = integrator_for(request);
  const SamplerType sampler = sampler_for(request.sampler);
  const Camera& view = camera ? *camera : scene.camera;
  view.validate();
  scene.validate();
  const Bounds2i crop = view.film.crop_pixels();
  Film film(crop.width(), crop.height());
  RenderOutcome outcome;
  if (request.aovs) outcome.aovs.emplace(film.width(), film.height());
  // Object motion compiled for this camera's exposure (not the scene camera's), so that any
  // camera renders the scene without copying it.
  TraceScene trace_scene(scene, std::make_shared<EmbreeDevice>(),
                         {.shutter = view.exposure_interval()});
  RenderSettings settings{.samples_per_pixel = request.samples_per_pixel,
                          .seed = request.seed,
                          .sampler = sampler,
                          .time_limit_s = request.time_limit_s,
                          .cancel = cancel};
  RenderStats stats = render(trace_scene, view, *integrator, settings, film, progress,
                             outcome.aovs ? &*outcome.aovs : nullptr);
  outcome.image = film.to_image();
  outcome.seconds = stats.seconds;
  outcome.rays = double(stats.rays.total());
  outcome.done = stats.samples_per_pixel;
  outcome.requested = request.samples_per_pixel;
  outcome.cancelled = stats.cancelled;
  outcome.time_limited = stats.partial && !stats.cancelled;
  outcome.warnings = scene.warnings;
  return outcome;
}

}  // namespace obscura::python
