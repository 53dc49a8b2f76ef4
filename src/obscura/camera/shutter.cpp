#include "obscura/camera/shutter.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

void validate(const Shutter& s) {
  if (!std::isfinite(s.open_s) || !std::isfinite(s.close_s) || s.close_s < s.open_s)
    throw Error("camera.shutter", "close must be at or after open; got open " +
                                      std::to_string(s.open_s) + " s, close " +
                                      std::to_string(s.close_s) + " s");
}

}  // namespace obscura
