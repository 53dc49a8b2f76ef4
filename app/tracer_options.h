// The tracer's part of `obscura render`: which integrator and sampler, how deep, for how long,
// which auxiliary outputs, and Ctrl-C handling.
#pragma once

#include <atomic>
#include <string>

#include <CLI/CLI.hpp>

#include "obscura/film/aov_buffers.h"
#include "obscura/io/image_io.h"
#include "obscura/math/sampler.h"
#include "obscura/render/renderer.h"

namespace obscura::app {

struct TracerOptions {
  std::string renderer_text = "path";  // --renderer as given: path | whitted | direct | raster
  Renderer renderer = {};              // renderer_text, parsed by validate
  std::string sampler = "sobol";       // sobol | independent
  int max_depth = 65;                  // path: scattering events per path; whitted: recursion depth
  double time_limit_s = 0;             // 0 = none
  bool aovs = false;                   // also write <output>.albedo/.normal/.depth/.id.exr
  bool spectral = false;               // spectral light transport (path tracer only)
  CLI::Option* spectral_option = nullptr;   // to know whether --spectral/--no-spectral was given
  CLI::Option* spp_option = nullptr;        // to know whether --spp was given
  CLI::Option* max_depth_option = nullptr;  // and --max-depth
};

void add_tracer_options(CLI::App& render, TracerOptions& options);
// Parses the renderer; throws UsageError for an unknown renderer or sampler, or a bad depth or
// time limit.
void validate(TracerOptions& options);
SamplerType sampler_type(const TracerOptions& options);
// --max-depth if given, else 0 (the integrator's default).
int max_depth(const TracerOptions& options);
// With --time-limit and no --spp, samples are unlimited (until the time is up).
int samples_per_pixel(const TracerOptions& options, int spp);
// While alive, SIGINT (Ctrl-C) and SIGTERM (what mpirun passes on to every rank for a Ctrl-C,
// and what farm managers send to cancel) set `requested()` instead of killing the process, so
// the render stops and the image rendered so far is still written. A second signal kills.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  static const std::atomic<bool>& requested();
};

}  // namespace obscura::app
