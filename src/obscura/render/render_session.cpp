#include "obscura/render/render_session.h"

#include <memory>
#include <string>

#include "obscura/math/error.h"
#include "obscura/render/camera_glare.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/embree_scene.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "obscura/trace/whitted.h"

namespace obscura {

namespace {

std::unique_ptr<Integrator> make_integrator(Renderer renderer, int max_depth) {
  switch (renderer) {
    case Renderer::kWhitted:
      return std::make_unique<WhittedIntegrator>(
          WhittedSettings{.max_depth = max_depth > 0 ? max_depth : WhittedSettings().max_depth});
    case Renderer::kDirect:
      return std::make_unique<DirectLightingIntegrator>();
    case Renderer::kPath:
    case Renderer::kRaster:
      break;
  }
  return std::make_unique<PathTracer>(
      PathTracerSettings{.max_depth = max_depth > 0 ? max_depth : PathTracerSettings().max_depth});
}

FrameStats trace_frame(const TraceScene& trace_scene, const Camera& camera,
                       const FrameSettings& settings, Film& film, AovBuffers* aovs,
                       const ProgressCallback& progress) {
  RenderSettings render_settings{.samples_per_pixel = settings.samples_per_pixel,
                                 .seed = settings.seed,
                                 .sampler = settings.sampler,
                                 .tile_size = tile_size(settings.renderer),
                                 .spectral = settings.spectral,
                                 .time_limit_s = settings.time_limit_s,
                                 .cancel = settings.cancel,
                                 .share = settings.share};
  RenderStats stats =
      render(trace_scene, camera, *make_integrator(settings.renderer, settings.max_depth),
             render_settings, film, progress, aovs);
  FrameStats frame;
  frame.seconds = stats.seconds;
  frame.rays = double(stats.rays.total());
  frame.done = stats.samples_per_pixel;
  frame.requested = settings.samples_per_pixel;
  frame.cancelled = stats.cancelled;
  frame.time_limited = stats.partial && !stats.cancelled;
  return frame;
}

void check_tracer_settings(const FrameSettings& settings) {
  if (settings.samples_per_pixel <= 0)
    throw Error("render_frame", "samples_per_pixel must be positive; got " +
                                    std::to_string(settings.samples_per_pixel));
  if (settings.max_depth < 0)
    throw Error("render_frame", "max_depth must be 0 (the default) or positive; got " +
                                    std::to_string(settings.max_depth));
}

FrameStats raster_frame(const Scene& scene, const Camera& camera, const FrameSettings& settings,
                        Film& film, AovBuffers* aovs, const ProgressCallback& progress) {
  raster::RenderSettings raster_settings = settings.raster;
  raster_settings.seed = settings.seed;
  raster_settings.time_limit_s = settings.time_limit_s;
  raster_settings.cancel = settings.cancel;
  raster_settings.share = settings.share;
  raster::RenderStats stats = raster::render(scene, camera, raster_settings, film, aovs, progress);
  FrameStats frame;
  frame.seconds = stats.seconds;
  frame.done = stats.frames;
  frame.requested = stats.frames_requested;
  frame.cancelled = stats.cancelled;
  frame.time_limited = stats.time_limited;
  frame.warnings = std::move(stats.warnings);
  frame.post_dof = std::move(stats.post_dof);
  return frame;
}

}  // namespace

struct RenderSession::CompiledTracer {
  std::shared_ptr<EmbreeDevice> device = std::make_shared<EmbreeDevice>();
  std::unique_ptr<TraceScene> scene;
};

RenderSession::RenderSession(const Scene& scene) : scene_(scene) {}
RenderSession::~RenderSession() = default;

FrameStats RenderSession::render(const Camera& camera, const FrameSettings& settings, Film& film,
                                 AovBuffers* aovs, const ProgressCallback& progress) {
  if (settings.spectral && settings.renderer != Renderer::kPath)
    throw Error("spectral rendering", "only the path tracer (renderer 'path') renders spectrally");
  if (!is_tracer(settings.renderer))
    return raster_frame(scene_, camera, settings, film, aovs, progress);
  check_tracer_settings(settings);
  // Object motion is compiled over the exposure of the camera being rendered, which need not be
  // the scene's own; a scene where nothing moves serves every exposure.
  const Shutter exposure = camera.exposure_interval();
  if (!tracer_) tracer_ = std::make_unique<CompiledTracer>();
  const TraceScene* compiled = tracer_->scene.get();
  if (!compiled || (compiled->has_motion() && (compiled->shutter().open_s != exposure.open_s ||
                                               compiled->shutter().close_s != exposure.close_s))) {
    tracer_->scene.reset();  // the old one's memory goes before the new one is built
    tracer_->scene = std::make_unique<TraceScene>(scene_, tracer_->device,
                                                  TraceSceneOptions{.shutter = exposure});
    ++tracer_compilations_;
  }
  return trace_frame(*tracer_->scene, camera, settings, film, aovs, progress);
}

RenderedFrame RenderSession::render(const Camera& camera, const FrameSettings& settings, bool aovs,
                                    const ProgressCallback& progress) {
  const Scene& scene = scene_;
  RenderedFrame frame;
  frame.renderer = settings.renderer;
  // What depends on the camera alone is settled before rendering: a camera that cannot have
  // glare or flare fails here, not after the render.
  if (settings.glare) frame.finish.glare = glare_finish(camera, *settings.glare);
  if (settings.flare) {
    frame.layers.push_back({std::string(kFlareLayer),
                            lens_flare_image(scene, camera, *settings.flare, &frame.flare_stats)});
    frame.layers.back().image.channel_names = {"R", "G", "B"};
    frame.finish.flare = true;
  }
  const Bounds2i crop = camera.film.crop_pixels();
  Film film(crop.width(), crop.height());
  if (aovs) frame.aovs.emplace(film.width(), film.height());
  frame.stats = render(camera, settings, film, frame.aovs ? &*frame.aovs : nullptr, progress);
  frame.film_sums = film.sums();
  if (std::optional<raster::PostDepthOfFieldInputs>& post = frame.stats.post_dof) {
    Image inputs(post->view_depth.width, post->view_depth.height, 2);
    inputs.channel_names = {"Z", "C"};
    for (size_t p = 0; p < post->view_depth.data.size(); ++p) {
      inputs.data[2 * p] = post->view_depth.data[p];
      inputs.data[2 * p + 1] = post->coc_px.data[p];
    }
    frame.layers.insert(frame.layers.begin(), {std::string(kDepthOfFieldLayer), std::move(inputs)});
    frame.finish.depth_of_field =
        DepthOfFieldFinish{.pixel_aspect = post->pixel_aspect, .settings = {}};
    post.reset();
  }
  return frame;
}

}  // namespace obscura
