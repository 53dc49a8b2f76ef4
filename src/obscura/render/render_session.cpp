#include "obscura/render/render_session.h"

#include <algorithm>
#include <memory>
#include <string>

#include "obscura/film/ground_truth_buffer.h"
#include "obscura/math/error.h"
#include "obscura/render/camera_glare.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/scene/ground_truth.h"

namespace obscura {

struct RenderSession::Compiled {
  std::string_view form = {};  // RendererBackend::compiled_form
  std::unique_ptr<CompiledScene> scene = nullptr;
  std::vector<uint32_t> changed = {};  // meshes posed again since compiled or brought up to date
};

RenderSession::RenderSession(const Scene& scene) : scene_(scene) {}
RenderSession::~RenderSession() = default;

const CompiledScene& RenderSession::compiled(Renderer renderer, const Shutter& interval) {
  const RendererBackend& backend = renderer.backend();
  auto it = std::find_if(compiled_.begin(), compiled_.end(),
                         [&](const Compiled& c) { return c.form == backend.compiled_form(); });
  if (it != compiled_.end()) {
    if (it->changed.empty() && it->scene->serves(interval)) return *it->scene;
    std::sort(it->changed.begin(), it->changed.end());
    it->changed.erase(std::unique(it->changed.begin(), it->changed.end()), it->changed.end());
    if (it->scene->update(scene_, it->changed, interval)) {
      it->changed.clear();
      ++updates_;
      return *it->scene;
    }
  }
  if (it == compiled_.end())
    it = compiled_.insert(compiled_.end(), Compiled{.form = backend.compiled_form()});
  it->scene.reset();  // the old compilation's memory goes before the new one is built
  it->changed.clear();
  it->scene = backend.compile(scene_, interval);
  ++compilations_;
  return *it->scene;
}

void RenderSession::scene_changed(std::span<const uint32_t> meshes) {
  for (Compiled& c : compiled_) c.changed.insert(c.changed.end(), meshes.begin(), meshes.end());
}

FrameStats RenderSession::render(const Camera& camera, const FrameSettings& settings, Film& film,
                                 AovBuffers* aovs, const ProgressCallback& progress) {
  const Renderer renderer = settings.renderer;
  if (settings.spectral && !renderer.capabilities().spectral)
    throw Error("spectral rendering", std::string("the renderer '") + renderer.name() +
                                          "' renders RGB only (the path tracer renders spectra)");
  // Object motion is compiled over the exposure of the camera being rendered, which need not be
  // the scene's own.
  const CompiledScene& scene = compiled(renderer, camera.exposure_interval());
  return renderer.backend().render(scene, camera, settings, film, aovs, progress);
}

GroundTruthBuffer RenderSession::ground_truth(const Camera& camera, const FrameSettings& settings,
                                              const GroundTruthTimes& times) {
  const Renderer renderer = settings.renderer;
  if (!renderer.capabilities().ground_truth)
    throw Error("ground truth", std::string("the renderer '") + renderer.name() + "' renders none");
  // Motion compiled over an interval holding both times (which may lie outside the shutter).
  const Shutter interval{
      .open_s = std::min({times.first_s, times.second_s, camera.shutter.open_s}),
      .close_s = std::max({times.first_s, times.second_s, camera.shutter.close_s})};
  const CompiledScene& scene = compiled(renderer, interval);
  return renderer.backend().ground_truth(scene, camera, settings, times);
}

RenderedFrame RenderSession::render(const Camera& camera, const FrameSettings& settings, bool aovs,
                                    const ProgressCallback& progress) {
  RenderedFrame frame;
  frame.renderer = settings.renderer;
  // What depends on the camera alone is settled before rendering: a camera that cannot have
  // glare or flare fails here, not after the render.
  if (settings.glare) frame.finish.glare = glare_finish(camera, *settings.glare);
  if (settings.flare) {
    // A cancel during the flare leaves out the sources not yet traced; the render below then
    // stops at once on the same flag, and the frame is marked interrupted.
    FlareSettings flare = *settings.flare;
    if (!flare.cancel) flare.cancel = settings.cancel;
    frame.layers.push_back(
        {std::string(kFlareLayer), lens_flare_image(scene_, camera, flare, &frame.flare_stats)});
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
