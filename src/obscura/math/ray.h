// A ray o + t·d for t in [t_min, t_max], at a time inside the shutter interval.
#pragma once

#include <limits>

#include "obscura/math/vector.h"

namespace obscura {

struct Ray {
  Point3f origin;
  Vector3f direction;  // not necessarily unit length; t is measured in multiples of it
  float t_min = 0;
  float t_max = std::numeric_limits<float>::infinity();
  float time = 0;

  Point3f at(float t) const { return origin + direction * t; }
};

}  // namespace obscura
