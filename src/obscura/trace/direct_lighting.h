// Direct lighting: emitted light seen directly plus one bounce of light from every point, spot
// and directional light (each with a shadow ray) and from the area lights (estimated by sampling
// a point on them and casting a shadow ray). This is the next-event-estimation step of a path
// tracer on its own (`obscura render --renderer direct`), and with punctual lights alone it is
// exact and noise-free: what the rasterizer computes, plus shadows.
#pragma once

#include "obscura/trace/integrator.h"

namespace obscura {

class DirectLightingIntegrator final : public Integrator {
 public:
  Rgb radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler, RayCounts& counts,
               FirstHit* first_hit = nullptr) const override;
};

}  // namespace obscura
