// An integrator estimates the radiance arriving along a camera ray. The render loop (render.h)
// owns pixels, samples and threads; integrators only answer "how much light comes down this ray".
#pragma once

#include <cstdint>

#include "obscura/color/rgb.h"
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

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Radiance along `ray`; draws its random numbers from `sampler` (after the camera's).
  virtual Rgb radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler,
                       RayCounts& counts) const = 0;
};

}  // namespace obscura
