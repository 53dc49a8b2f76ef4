#include "obscura/camera/shutter.h"

#include <cmath>
#include <string>

#include "obscura/camera/number_text.h"
#include "obscura/math/error.h"

namespace obscura {

void validate(const Shutter& s) {
  if (!std::isfinite(s.open_s) || !std::isfinite(s.close_s) || s.close_s < s.open_s)
    throw Error("camera.shutter", "close must be at or after open; got open " +
                                      number_text(s.open_s) + " s, close " +
                                      number_text(s.close_s) + " s");
}

}  // namespace obscura
