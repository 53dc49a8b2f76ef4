#include "raster_options.h"

#include "obscura/render/renderer_backend.h"
#include "option_ranges.h"
#include "usage_error.h"

namespace obscura::app {

void add_raster_options(CLI::App& render, RasterOptions& o) {
  o.registered = {
      render.add_option("--msaa", o.msaa, "raster: multisample anti-aliasing, 1, 4 or 8 samples")
          ->check(integer_in(1, 8)),
      render.add_option("--shading", o.shading,
                        "raster: flat, gouraud, phong (per pixel; default) or blinn-phong "
                        "(per pixel, half-vector lobe for Phong materials)"),
      render.add_flag("--cull", o.cull, "raster: cull back faces"),
      render.add_flag("--wireframe", o.wireframe, "raster: draw triangle edges over the image"),
      render
          .add_option("--shadow-map", o.shadow_map_size,
                      "raster: shadow map size (texels per side) for directional and spot "
                      "lights; 0: no shadows (default 1024)")
          ->check(integer_in(0, 16384))};
}

void reject_unless_raster(const std::vector<CLI::Option*>& registered, Renderer renderer) {
  if (renderer.capabilities().raster_settings) return;
  for (const CLI::Option* option : registered)
    if (option && option->count() > 0)
      throw UsageError(option->get_name() +
                       " applies to --renderer raster only (the renderer is '" + renderer.name() +
                       "')");
}

void validate(const RasterOptions& o, Renderer renderer) {
  reject_unless_raster(o.registered, renderer);
  if (!renderer.capabilities().raster_settings) return;
  if (o.msaa != 1 && o.msaa != 4 && o.msaa != 8)
    throw UsageError("--msaa must be 1, 4 or 8 samples; got " + std::to_string(o.msaa));
  if (o.shadow_map_size < 0 || o.shadow_map_size > 16384)
    throw UsageError("--shadow-map must be 0 (no shadows) to 16384 texels; got " +
                     std::to_string(o.shadow_map_size));
  if (!raster::parse_shading_mode(o.shading))
    throw UsageError("--shading must be flat, gouraud, phong or blinn-phong; got '" + o.shading +
                     "'");
}

void apply_raster_options(const RasterOptions& o, raster::RenderSettings& s) {
  s.msaa_samples = o.msaa;
  s.shading = raster::parse_shading_mode(o.shading).value_or(raster::ShadingMode::kPhong);
  s.cull_back_faces = o.cull;
  s.wireframe = o.wireframe;
  s.shadow_map_size = o.shadow_map_size;
}

}  // namespace obscura::app
