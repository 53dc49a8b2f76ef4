// A test lens: a biconvex element, R = ±100 mm, 1 mm thick, n 1.5 (f ≈ 100 mm), with the stop
// at its front vertex. Nothing is in front of the stop, so every chief ray crosses the axis
// there; at f/8 its aberrations blur a point by a few micrometres, far below a pixel.
#pragma once

#include "obscura/camera/lens_prescription.h"

namespace obscura::test {

inline LensPrescription thin_element() {
  LensPrescription p;
  p.name = "thin element";
  p.surfaces = {
      {.radius_mm = 0, .thickness_mm = 0, .n_d = 1, .aperture_diameter_mm = 12, .is_stop = true},
      {.radius_mm = 100, .thickness_mm = 1, .n_d = 1.5, .aperture_diameter_mm = 30},
      {.radius_mm = -100, .n_d = 1, .aperture_diameter_mm = 30},
  };
  return p;
}

}  // namespace obscura::test
