// An integrator estimates the radiance arriving along a camera ray. The render loop (render.h)
// owns pixels, samples and threads; integrators only answer "how much light comes down this ray".
#pragma once

#include <cstdint>

#include "obscura/color/rgb.h"
#include "obscura/color/sampled_wavelengths.h"
#include "obscura/math/ray.h"
#include "obscura/math/sampler.h"
#include "obscura/trace/trace_scene.h"

namespace obscura {

// Per-thread counters, summed by the render loop for its statistics.
struct RayCounts {
  uint64_t camera = 0, shadow = 0, bounce = 0;
  uint64_t total() const { return camera + shadow + bounce; }
  RayCounts& operator+=(const RayCounts& o) {
    camera += o.camera, shadow += o.shadow, bounce += o.bounce;
    return *this;
  }
};

// What the camera ray met first: the auxiliary outputs (AOVs) denoisers and compositors use.
struct FirstHit {
  bool hit = false;
  Rgb albedo;        // the surface's reflectance (see AnyBsdf::albedo)
  Normal3f normal;   // world-space shading normal, facing the camera
  Point3f position;  // world-space point hit
  float range = 0;   // distance from the ray origin (m)
  uint32_t id = 0;   // the mesh hit
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Radiance along `ray`; draws its random numbers from `sampler` (after the camera's). When
  // `first_hit` is given, it receives the first surface the ray met.
  virtual Rgb radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler, RayCounts& counts,
                       FirstHit* first_hit = nullptr) const = 0;

  // Spectral mode: the radiance along `ray` at the path's wavelengths (channel i at
  // wavelengths.nm(i)), drawing from `sampler` as radiance() does; may terminate the secondary
  // wavelengths. Integrators that do not support_spectral() throw obscura::Error.
  virtual bool supports_spectral() const { return false; }
  virtual Rgb spectral_radiance(const TraceScene& scene, const Ray& ray,
                                SampledWavelengths& wavelengths, Sampler& sampler,
                                RayCounts& counts, FirstHit* first_hit = nullptr) const;
};

// Fills `first_hit` (if not null) from a hit of a ray with unit direction `direction`.
void record_first_hit(const TraceScene& scene, const SurfaceHit& hit, Vector3f direction,
                      FirstHit* first_hit);

}  // namespace obscura
