#include "obscura/render/frame_request.h"
#include "obscura/render/renderer_backend.h"

namespace obscura {

ResolvedFrameRequest resolve_frame_request(const FrameRequest& request,
                                           const SceneRenderSettings& scene, Renderer renderer) {
  ResolvedFrameRequest r;
  r.samples_per_pixel =
      request.samples_per_pixel.value_or(scene.samples_per_pixel.value_or(kDefaultSamplesPerPixel));
  r.seed = request.seed.value_or(scene.seed.value_or(0));
  if (request.spectral)
    r.spectral = *request.spectral;
  else if (scene.spectral && renderer.capabilities().spectral)
    r.spectral = *scene.spectral;
  if (request.glare || request.glare_strength || scene.glare_strength) {
    GlareSettings glare;
    glare.strength = request.glare_strength.value_or(scene.glare_strength.value_or(1.0));
    if (request.glare_radius_px)
      glare.radius_px = *request.glare_radius_px;
    else if (scene.glare_radius_px)
      glare.radius_px = *scene.glare_radius_px;
    r.glare = glare;
  }
  if (request.flare.value_or(scene.flare.value_or(false))) r.flare = FlareSettings{};
  // REYES's knobs: the caller's, else the scene file's `render.reyes` block, else the defaults.
  const reyes::ReyesSettings defaults;
  const SceneReyesSettings& file = scene.reyes;
  r.reyes.shading_rate =
      request.reyes_shading_rate.value_or(file.shading_rate.value_or(defaults.shading_rate));
  r.reyes.grid_size = request.reyes_grid_size.value_or(file.grid_size.value_or(defaults.grid_size));
  r.reyes.bucket_size =
      request.reyes_bucket_size.value_or(file.bucket_size.value_or(defaults.bucket_size));
  r.reyes.pixel_samples =
      request.reyes_pixel_samples.value_or(file.pixel_samples.value_or(defaults.pixel_samples));
  r.reyes.eye_splits =
      request.reyes_eye_splits.value_or(file.eye_splits.value_or(defaults.eye_splits));
  return r;
}

}  // namespace obscura
