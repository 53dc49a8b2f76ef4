// The projection of a camera whose rays come from a lens system (lens_system.h): a real lens
// prescription traced surface by surface, focused by moving the lens, with the iris of the
// camera's Aperture. The camera's ThinLens settings it shares: focus_distance_m (measured from
// the sensor, as camera space's origin is the sensor for this projection) and the aperture's
// blades and rotation; its f-number is its own (below). See focused_lens_system.h for the rays.
#pragma once

#include <memory>
#include <optional>

#include "obscura/camera/lens_coating.h"
#include "obscura/camera/lens_system.h"

namespace obscura {

struct LensSystemProjection {
  std::shared_ptr<const LensSystem> lens;  // required
  // The sensor's width, spanning the image's width; its height follows the image's aspect.
  double sensor_width_mm = 36;
  // Stops the iris down from the lens's widest opening (≥ lens->f_number()); nothing: wide open.
  std::optional<double> f_number;
  // The anti-reflection coating of its air–glass surfaces: what its ghost flares reflect
  // (lens_ghosts.h). A single quarter-wave layer of magnesium fluoride by default.
  LensCoating coating = quarter_wave_coating();
};

// Throws obscura::Error naming the field: no lens, a sensor width that is not positive, an
// f-number below the lens's widest, an invalid coating.
void validate(const LensSystemProjection& p);

}  // namespace obscura
