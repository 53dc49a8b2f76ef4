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
  return r;
}

}  // namespace obscura
