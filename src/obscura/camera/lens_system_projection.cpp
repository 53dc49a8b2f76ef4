#include "obscura/camera/lens_system_projection.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

void validate(const LensSystemProjection& p) {
  if (!p.lens) throw Error("camera.lens", "a lens-system camera needs a lens");
  if (!(p.sensor_width_mm > 0) || !std::isfinite(p.sensor_width_mm))
    throw Error("camera.sensor_width_mm",
                "must be positive; got " + number_text(p.sensor_width_mm));
  if (p.f_number) {
    const double widest = p.lens->f_number();
    if (!std::isfinite(*p.f_number) || !(*p.f_number >= widest * (1 - 1e-3)))
      throw Error("camera.f_number", "lens '" + p.lens->name() + "' opens to f/" +
                                         number_text(widest) + " at most; got f/" +
                                         number_text(*p.f_number));
  }
  validate(p.coating);
}

}  // namespace obscura
