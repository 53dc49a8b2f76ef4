#include "tracer_options.h"

#include <csignal>
#include <limits>
#include <optional>

#include "obscura/io/image_io.h"
#include "obscura/render/renderer_backend.h"
#include "option_ranges.h"
#include "partial_render.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

std::atomic<bool> interrupt_requested{false};

extern "C" void on_interrupt(int signal) {
  note_interrupt_signal(signal);  // the exit status: 130 for SIGINT, 143 for SIGTERM
  interrupt_requested.store(true);
  std::signal(signal, SIG_DFL);  // a second Ctrl-C ends the process at once
}

// "path (physically based path tracer), …": the renderer table's rows.
std::string renderer_help() {
  std::string help;
  for (const Renderer& r : renderers())
    help += (help.empty() ? "" : ", ") + std::string(r.name()) + " (" + r.backend().summary() + ")";
  return help;
}

// The renderers with spectral light transport, for messages: "path".
std::string spectral_renderers() {
  std::string names;
  for (const Renderer& r : renderers())
    if (r.capabilities().spectral) names += (names.empty() ? "" : ", ") + std::string(r.name());
  return names;
}

}  // namespace

void add_tracer_options(CLI::App& render, TracerOptions& o) {
  render.add_option("--renderer", o.renderer_text, renderer_help())->capture_default_str();
  render.add_option("--sampler", o.sampler, "sobol (Owen-scrambled) or independent")
      ->capture_default_str();
  o.max_depth_option =
      render
          .add_option(
              "--max-depth", o.max_depth,
              "path: scattering events per path (default 65); whitted: mirror/refraction depth "
              "(default 8)")
          ->check(integer_in(1, kMaxTraceDepth));
  render
      .add_option("--time-limit", o.time_limit_s,
                  "Stop after about this many seconds (without --spp: as many samples as fit)")
      ->check(number_in(0, kMaxTimeLimitS));
  o.spectral_option = render.add_flag(
      "--spectral,!--no-spectral", o.spectral,
      "Spectral light transport (path tracer only): wavelengths per path, colours lifted to "
      "spectra, dispersive glass; whitted, direct and raster refuse it. --no-spectral: RGB "
      "transport even where the scene file asks for spectral");
  render.add_flag(
      "--aovs", o.aovs,
      "Also write albedo, normal, depth (along the optical axis), range (along the ray) and id "
      "images beside the output (.exr)");
}

void validate(TracerOptions& o) {
  std::optional<Renderer> renderer = parse_renderer(o.renderer_text);
  if (!renderer)
    throw UsageError("--renderer must be " + renderer_names() + "; got '" + o.renderer_text + "'");
  o.renderer = *renderer;
  if (!parse_sampler_type(o.sampler))
    throw UsageError("--sampler must be sobol or independent; got '" + o.sampler + "'");
  if (o.spectral && !o.renderer.capabilities().spectral)
    throw UsageError("--spectral needs a renderer with spectral light transport (" +
                     spectral_renderers() + "); '" + o.renderer_text + "' renders RGB only");
  bool depth_given = o.max_depth_option && o.max_depth_option->count() > 0;
  if (depth_given && o.max_depth < 1)
    throw UsageError("--max-depth must be at least 1; got " + std::to_string(o.max_depth));
  if (!(o.time_limit_s >= 0))
    throw UsageError("--time-limit must be a number of seconds ≥ 0; got " +
                     std::to_string(o.time_limit_s));
}

SamplerType sampler_type(const TracerOptions& o) {
  return parse_sampler_type(o.sampler).value_or(SamplerType::kSobol);
}

int max_depth(const TracerOptions& o) {
  return o.max_depth_option && o.max_depth_option->count() > 0 ? o.max_depth : 0;
}

int samples_per_pixel(const TracerOptions& o, int spp) {
  bool spp_given = o.spp_option && o.spp_option->count() > 0;
  return o.time_limit_s > 0 && !spp_given ? std::numeric_limits<int>::max() / 2 : spp;
}

InterruptGuard::InterruptGuard() {
  interrupt_requested.store(false);
  note_interrupt_signal(0);
  std::signal(SIGINT, on_interrupt);
  // What mpirun sends every rank on Ctrl-C, and farm managers to cancel a task.
  std::signal(SIGTERM, on_interrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

const std::atomic<bool>& InterruptGuard::requested() {
  return interrupt_requested;
}

}  // namespace obscura::app
