// Direct lighting: emitted light seen directly plus one bounce of light from the area lights,
// estimated by sampling a point on the lights and casting a shadow ray. This is the
// next-event-estimation step of a path tracer on its own (`obscura render --renderer direct`).
#pragma once

#include "obscura/trace/integrator.h"

namespace obscura {

class DirectLightingIntegrator final : public Integrator {
 public:
  Rgb radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler, RayCounts& counts,
               FirstHit* first_hit = nullptr) const override;
};

}  // namespace obscura
