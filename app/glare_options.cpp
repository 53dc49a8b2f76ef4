#include "glare_options.h"

#include "option_ranges.h"

namespace obscura::app {

void add_glare_options(CLI::App& render, GlareOptions& o) {
  render.add_flag("--glare", o.on,
                  "Diffraction glare: spread the HDR frame by the aperture's point-spread "
                  "function (Airy pattern, or a starburst with --aperture-blades), either "
                  "renderer; perspective and lens-system cameras");
  render
      .add_option("--glare-strength", o.strength,
                  "Scale of the light the glare spreads (1 = the aperture's own diffraction, "
                  "above 1 artistic); implies --glare")
      ->check(number_in(0, 1000));
  render
      .add_option("--glare-radius", o.radius_px,
                  "Pixels from a light where the glare is cut off (default 256)")
      ->check(integer_in(1, 4096));
}

}  // namespace obscura::app
