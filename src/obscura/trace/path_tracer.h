// A unidirectional path tracer: from the camera, bounce by sampling the BSDF; at every
// non-specular vertex also sample a light (next-event estimation) and combine the two
// strategies with multiple importance sampling (Veach's power heuristic, β = 2). Russian
// roulette ends paths whose throughput has become small, without bias.
//
// Spectral mode (spectral_radiance) follows the same path with radiance and throughput at the
// path's wavelengths instead of RGB: materials and lights are lifted to spectra where they are
// met (trace_material.h), and a dispersive dielectric keeps only the hero wavelength.
#pragma once

#include "obscura/trace/integrator.h"

namespace obscura {

struct PathTracerSettings {
  // Scattering events per path, at most (1 = direct light only). Cycles' max_bounces = N
  // corresponds to N + 1.
  int max_depth = 65;
  // Vertices before Russian roulette may end a path.
  int roulette_depth = 3;
  // Which strategies reach the lights: both weighted by MIS (the default), or only one of them
  // (unweighted; for tests showing the three converge to the same image).
  enum class Strategy { kMis, kLightOnly, kBsdfOnly };
  Strategy strategy = Strategy::kMis;
};

class PathTracer final : public Integrator {
 public:
  explicit PathTracer(PathTracerSettings settings = {}) : settings_(settings) {}
  Rgb radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler, RayCounts& counts,
               FirstHit* first_hit = nullptr) const override;
  bool supports_spectral() const override { return true; }
  Rgb spectral_radiance(const TraceScene& scene, const Ray& ray, SampledWavelengths& wavelengths,
                        Sampler& sampler, RayCounts& counts,
                        FirstHit* first_hit = nullptr) const override;

 private:
  // Both modes: RGB where `wavelengths` is null, else at its wavelengths.
  Rgb trace(const TraceScene& scene, const Ray& ray, SampledWavelengths* wavelengths,
            Sampler& sampler, RayCounts& counts, FirstHit* first_hit) const;
  PathTracerSettings settings_;
};

// The power heuristic weight of a sample from strategy f against strategy g (one sample each).
inline float power_heuristic(float pdf_f, float pdf_g) {
  float f2 = pdf_f * pdf_f, g2 = pdf_g * pdf_g;
  return f2 + g2 > 0 ? f2 / (f2 + g2) : 0.f;
}

}  // namespace obscura
