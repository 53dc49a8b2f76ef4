// The tracer's back ends: the path tracer, the Whitted tracer and direct lighting, three
// integrators (trace/integrator.h) over one compiled scene — an Embree BVH with the scene's
// lights and materials (trace/trace_scene.h) — which a session shares between them.
#include <memory>
#include <string>

#include "obscura/film/ground_truth_buffer.h"
#include "obscura/math/error.h"
#include "obscura/render/backends.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/scene/surface_motion.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/embree_scene.h"
#include "obscura/trace/ground_truth_render.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "obscura/trace/whitted.h"

namespace obscura {

namespace {

class CompiledTraceScene final : public CompiledScene {
 public:
  CompiledTraceScene(const Scene& scene, const Shutter& exposure)
      : scene_(scene),
        trace_(scene, std::make_shared<EmbreeDevice>(), TraceSceneOptions{.shutter = exposure}) {}

  // Object motion is compiled over one interval; a scene where nothing moves serves any.
  bool serves(const Shutter& exposure) const override { return trace_.serves(exposure); }
  bool update(const Scene& scene, std::span<const uint32_t> changed,
              const Shutter& exposure) override {
    return trace_.update(scene, changed, exposure);
  }
  const Scene& scene() const { return scene_; }
  const TraceScene& trace() const { return trace_; }

 private:
  const Scene& scene_;
  TraceScene trace_;
};

using IntegratorFactory = std::unique_ptr<Integrator> (*)(int max_depth);

class TracerBackend final : public RendererBackend {
 public:
  TracerBackend(const char* name, const char* summary, bool spectral, IntegratorFactory make)
      : RendererBackend(name, summary,
                        {.takes_samples_per_pixel = true,
                         .progress_unit = "samples per pixel",
                         .albedo = true,
                         .spectral = spectral,
                         .ground_truth = true,
                         .raster_settings = false,
                         .tile_size = RenderSettings().tile_size}),
        make_integrator_(make) {}

  std::string_view compiled_form() const override { return "embree"; }

  std::unique_ptr<CompiledScene> compile(const Scene& scene,
                                         const Shutter& exposure) const override {
    return std::make_unique<CompiledTraceScene>(scene, exposure);
  }

  FrameStats render(const CompiledScene& compiled, const Camera& camera,
                    const FrameSettings& settings, Film& film, AovBuffers* aovs,
                    const ProgressCallback& progress) const override {
    if (settings.samples_per_pixel <= 0)
      throw Error("render_frame", "samples_per_pixel must be positive; got " +
                                      std::to_string(settings.samples_per_pixel));
    if (settings.max_depth < 0)
      throw Error("render_frame", "max_depth must be 0 (the default) or positive; got " +
                                      std::to_string(settings.max_depth));
    const RenderSettings render_settings{.samples_per_pixel = settings.samples_per_pixel,
                                         .seed = settings.seed,
                                         .sampler = settings.sampler,
                                         .tile_size = capabilities().tile_size,
                                         .spectral = settings.spectral,
                                         .time_limit_s = settings.time_limit_s,
                                         .cancel = settings.cancel,
                                         .share = settings.share};
    const RenderStats stats = obscura::render(
        static_cast<const CompiledTraceScene&>(compiled).trace(), camera,
        *make_integrator_(settings.max_depth), render_settings, film, progress, aovs);
    FrameStats frame;
    frame.seconds = stats.seconds;
    frame.rays = double(stats.rays.total());
    frame.done = stats.samples_per_pixel;
    frame.requested = settings.samples_per_pixel;
    frame.cancelled = stats.cancelled;
    frame.time_limited = stats.partial && !stats.cancelled;
    return frame;
  }

  GroundTruthBuffer ground_truth(const CompiledScene& compiled, const Camera& camera,
                                 const FrameSettings& settings,
                                 const GroundTruthTimes& times) const override {
    const auto& traced = static_cast<const CompiledTraceScene&>(compiled);
    return render_ground_truth(traced.trace(), SurfaceMotion(traced.scene()), camera, times,
                               settings.cancel);
  }

 private:
  IntegratorFactory make_integrator_;
};

// `max_depth` 0 takes each integrator's default.
std::unique_ptr<Integrator> make_path_tracer(int max_depth) {
  return std::make_unique<PathTracer>(
      PathTracerSettings{.max_depth = max_depth > 0 ? max_depth : PathTracerSettings().max_depth});
}

std::unique_ptr<Integrator> make_whitted(int max_depth) {
  return std::make_unique<WhittedIntegrator>(
      WhittedSettings{.max_depth = max_depth > 0 ? max_depth : WhittedSettings().max_depth});
}

std::unique_ptr<Integrator> make_direct_lighting(int) {
  return std::make_unique<DirectLightingIntegrator>();
}

}  // namespace

const RendererBackend& path_tracer_backend() {
  static const TracerBackend backend("path", "physically based path tracer", true,
                                     make_path_tracer);
  return backend;
}

const RendererBackend& whitted_backend() {
  static const TracerBackend backend("whitted", "Whitted-style recursive ray tracer", false,
                                     make_whitted);
  return backend;
}

const RendererBackend& direct_lighting_backend() {
  static const TracerBackend backend("direct", "direct lighting only", false, make_direct_lighting);
  return backend;
}

}  // namespace obscura
