#include "obscura/camera/orthographic.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

void validate(const Orthographic& o) {
  if (!(o.view_height_m > 0) || !std::isfinite(o.view_height_m))
    throw Error("camera.view_height_m", "must be positive; got " + number_text(o.view_height_m));
  if (o.view_width_m && (!(*o.view_width_m > 0) || !std::isfinite(*o.view_width_m)))
    throw Error("camera.view_width_m", "must be positive; got " + number_text(*o.view_width_m));
}

}  // namespace obscura
