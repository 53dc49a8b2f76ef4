#include "reyes_options.h"

#include <string>

#include "obscura/render/renderer_backend.h"
#include "usage_error.h"

namespace obscura::app {

void add_reyes_options(CLI::App& render, ReyesOptions& o) {
  o.registered = {
      render.add_option("--reyes-shading-rate", o.shading_rate,
                        "reyes: micropolygon area in pixels (default 1; 1/64 to 1024)"),
      render.add_option("--reyes-grid-size", o.grid_size,
                        "reyes: most micropolygons per shaded grid (default 256)"),
      render.add_option("--reyes-bucket-size", o.bucket_size,
                        "reyes: side of the buckets sampled at once, pixels (default 16; ≤ 64)"),
      render.add_option("--reyes-pixel-samples", o.pixel_samples,
                        "reyes: visibility samples per pixel, each with its own time and lens "
                        "point (default 16)"),
      render.add_option("--reyes-eye-splits", o.eye_splits,
                        "reyes: splits of a surface crossing the near plane before it is dropped "
                        "(default 8)")};
}

void validate(const ReyesOptions& o, Renderer renderer) {
  if (renderer.name() == std::string("reyes")) return;
  for (const CLI::Option* option : o.registered)
    if (option && option->count() > 0)
      throw UsageError(option->get_name() + " applies to --renderer reyes only (the renderer is '" +
                       renderer.name() + "')");
}

void request_reyes_options(const ReyesOptions& o, FrameRequest& r) {
  auto given = [&](size_t k) { return k < o.registered.size() && o.registered[k]->count() > 0; };
  if (given(0)) r.reyes_shading_rate = o.shading_rate;
  if (given(1)) r.reyes_grid_size = o.grid_size;
  if (given(2)) r.reyes_bucket_size = o.bucket_size;
  if (given(3)) r.reyes_pixel_samples = o.pixel_samples;
  if (given(4)) r.reyes_eye_splits = o.eye_splits;
}

}  // namespace obscura::app
