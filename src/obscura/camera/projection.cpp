#include "obscura/camera/projection.h"

namespace obscura {

std::string_view projection_name(const Projection& p) {
  return std::visit(Overloaded{
                        [](const Perspective&) { return "perspective"; },
                        [](const Orthographic&) { return "orthographic"; },
                        [](const Equirectangular&) { return "spherical"; },
                        [](const Fisheye&) { return "fisheye"; },
                        [](const CalibratedProjection&) { return "calibrated"; },
                        [](const LensSystemProjection&) { return "lens-system"; },
                    },
                    p);
}

}  // namespace obscura
