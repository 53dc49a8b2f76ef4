#include "obscura/camera/shutter.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

void validate(const Shutter& s) {
  if (!std::isfinite(s.open_s) || !std::isfinite(s.close_s) || s.close_s < s.open_s)
    throw Error("camera.shutter", "close must be at or after open; got open " +
                                      number_text(s.open_s) + " s, close " +
                                      number_text(s.close_s) + " s");
  if (!std::isfinite(s.line_time_s) || s.line_time_s < 0)
    throw Error("camera.shutter.line_time",
                "must be ≥ 0 seconds (0: a global shutter); got " + number_text(s.line_time_s));
}

const char* readout_name(Readout r) {
  switch (r) {
    case Readout::top_to_bottom:
      return "top-to-bottom";
    case Readout::bottom_to_top:
      return "bottom-to-top";
    case Readout::left_to_right:
      return "left-to-right";
    case Readout::right_to_left:
      return "right-to-left";
  }
  return "top-to-bottom";
}

}  // namespace obscura

namespace obscura {

std::optional<Readout> readout_from_name(std::string_view name) {
  for (Readout r : {Readout::top_to_bottom, Readout::bottom_to_top, Readout::left_to_right,
                    Readout::right_to_left})
    if (name == readout_name(r)) return r;
  return std::nullopt;
}

}  // namespace obscura
