// The render loop shared by the tracer's integrators: tiles in parallel, samples per pixel, one
// camera ray per sample, the pixel's mean into the film.
#pragma once

#include <cstdint>

#include "obscura/camera/camera.h"
#include "obscura/film/film.h"
#include "obscura/film/tiles.h"
#include "obscura/trace/integrator.h"

namespace obscura {

struct RenderSettings {
  int samples_per_pixel = 16;  // > 0
  uint64_t seed = 0;
  SamplerType sampler = SamplerType::kSobol;
  int tile_size = 16;
};

struct RenderStats {
  RayCounts rays;
  double seconds = 0;
};

// Renders the camera's crop window (the full image by default) into `film`, which must have
// the crop's size. Each sample draws, in order, a filter offset (2D), a lens point (2D) and a
// time in the shutter interval (1D) before the integrator's numbers; its radiance is scaled by
// the camera's exposure. Deterministic: every random number is a function of
// (seed, pixel, sample, dimension) and each pixel sums its own samples in order, so the image is
// bit-identical for any thread count.
RenderStats render(const TraceScene& scene, const Camera& camera, const Integrator& integrator,
                   const RenderSettings& settings, Film& film,
                   const ProgressCallback& progress = {});

}  // namespace obscura
