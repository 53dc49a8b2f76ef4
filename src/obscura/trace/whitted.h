// Whitted-style ray tracing (Whitted 1980): direct light with shadow rays at every surface, plus
// perfect mirror reflection and refraction followed up to a depth. No indirect diffuse light: the
// classic look, fast and noise-free except for sampled area lights.
//
// The tree of reflected and refracted rays is walked with an explicit stack, not by recursion, so
// no depth overflows the thread's stack; and each camera ray traces at most kRayBudget rays, so
// glass (which splits every ray in two) cannot make the work grow as 2^depth.
#pragma once

#include "obscura/trace/integrator.h"

namespace obscura {

struct WhittedSettings {
  int max_depth = 8;  // mirror/refraction generations after the camera ray
};

class WhittedIntegrator final : public Integrator {
 public:
  // Rays per camera ray, the camera ray included. A vertex spends one ray of its subtree's
  // budget and splits the rest evenly between its branches, so a full binary tree of depth 11
  // (4095 rays) is traced whole (images are what recursion gave, up to that depth), a chain of
  // single branches (mirrors) may run 4096 deep, and deeper splits are dropped.
  static constexpr int kRayBudget = 4096;

  explicit WhittedIntegrator(WhittedSettings settings = {}) : settings_(settings) {}
  Rgb radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler, RayCounts& counts,
               FirstHit* first_hit = nullptr) const override;

 private:
  WhittedSettings settings_;
};

}  // namespace obscura
