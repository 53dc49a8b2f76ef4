// Whitted-style ray tracing (Whitted 1980): direct light with shadow rays at every surface, plus
// perfect mirror reflection and refraction followed recursively up to a depth. No indirect
// diffuse light: the classic look, fast and noise-free except for sampled area lights.
#pragma once

#include "obscura/trace/integrator.h"

namespace obscura {

struct WhittedSettings {
  int max_depth = 8;  // mirror/refraction generations after the camera ray
};

class WhittedIntegrator final : public Integrator {
 public:
  explicit WhittedIntegrator(WhittedSettings settings = {}) : settings_(settings) {}
  Rgb radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler, RayCounts& counts,
               FirstHit* first_hit = nullptr) const override;

 private:
  Rgb trace(const TraceScene& scene, const Ray& ray, Sampler& sampler, RayCounts& counts, int depth,
            FirstHit* first_hit) const;
  WhittedSettings settings_;
};

}  // namespace obscura
