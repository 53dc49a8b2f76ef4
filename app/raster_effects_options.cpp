#include "raster_effects_options.h"

#include "obscura/render/renderer_backend.h"
#include "option_ranges.h"
#include "raster_options.h"
#include "usage_error.h"

namespace obscura::app {

void add_raster_effects_options(CLI::App& render, RasterEffectsOptions& o) {
  o.registered = {
      render.add_option("--raster-dof", o.dof,
                        "raster: depth of field by 'accumulate' (renders through jittered lens "
                        "points; default), 'post' (one render blurred by the z-buffer's circle "
                        "of confusion) or 'off'"),
      render
          .add_option("--raster-samples", o.samples,
                      "raster: frames accumulated for depth of field and motion blur "
                      "(default 32)")
          ->check(integer_in(1, kMaxRasterSamples))};
}

void validate(const RasterEffectsOptions& o, Renderer renderer) {
  reject_unless_raster(o.registered, renderer);
  if (!renderer.capabilities().raster_settings) return;
  if (!raster::parse_depth_of_field_method(o.dof))
    throw UsageError("--raster-dof must be off, accumulate or post; got '" + o.dof + "'");
  if (o.samples < 1)
    throw UsageError("--raster-samples must be a positive number of frames; got " +
                     std::to_string(o.samples));
}

void apply_raster_effects_options(const RasterEffectsOptions& o, raster::RenderSettings& s) {
  s.depth_of_field =
      raster::parse_depth_of_field_method(o.dof).value_or(raster::DepthOfFieldMethod::kAccumulate);
  s.effect_samples = o.samples;
}

}  // namespace obscura::app
