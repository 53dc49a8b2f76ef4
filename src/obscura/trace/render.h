// The render loop shared by the tracer's integrators: tiles in parallel, samples per pixel, one
// camera ray per sample, the pixel's mean into the film.
#pragma once

#include <atomic>
#include <cstdint>

#include "obscura/camera/camera.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/film/tiles.h"
#include "obscura/film/work_share.h"
#include "obscura/trace/integrator.h"

namespace obscura {

struct RenderSettings {
  int samples_per_pixel = 16;  // > 0; the most a time-limited render takes
  uint64_t seed = 0;
  SamplerType sampler = SamplerType::kSobol;
  int tile_size = 16;
  // Spectral light transport (the integrator must support_spectral(): the path tracer): each
  // sample carries wavelengths (hero-wavelength sampling, color/sampled_wavelengths.h) and its
  // spectral radiance reaches the film through the CIE 1931 observer as working RGB. Off: RGB
  // transport, the default, unchanged by this switch.
  bool spectral = false;
  // Stop starting new passes once the next one would end after this many seconds (0 = no
  // limit). At least one pass is always rendered.
  double time_limit_s = 0;
  // Set from another thread (a signal handler) to stop: tiles not yet started are skipped.
  const std::atomic<bool>* cancel = nullptr;
  // The tiles this process renders when several render the frame together (tiles of tile_size,
  // dealt as TileDeal deals them), and how they agree to stop. Default: all of them, alone.
  WorkShare share = {};
};

struct RenderStats {
  RayCounts rays;
  double seconds = 0;
  int samples_per_pixel = 0;  // completed in every pixel
  bool partial = false;       // stopped early: by the time limit or by `cancel`
  bool cancelled = false;     // `cancel` was set (some pixels may have fewer samples)
};

// Renders the camera's crop window (the full image by default) into `film` (and `aovs`, if
// given), which must have the crop's size. Each sample draws the camera's numbers in the order
// every renderer draws them (camera/camera_sample.h) before the integrator's; its radiance is
// scaled by the camera's exposure.
//
// Samples are rendered in passes over every tile, paced and stopped as every renderer's are
// (film/pass_schedule.h), so that a time limit or a cancellation leaves an evenly sampled image.
// Deterministic: every random number is a function of (seed, pixel, sample, dimension) and each
// pixel sums its own samples in order, so the image is bit-identical for any thread count (for
// time-limited renders: for the same pass count). With a share of the work, only the share's
// tiles are rendered (the others stay empty) and each of them is bit-identical to the same tile
// of a lone render; every part calls share.settle once per pass.
RenderStats render(const TraceScene& scene, const Camera& camera, const Integrator& integrator,
                   const RenderSettings& settings, Film& film,
                   const ProgressCallback& progress = {}, AovBuffers* aovs = nullptr);

}  // namespace obscura
