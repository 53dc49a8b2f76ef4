// Ideal diffuse reflection: f = ρ/π in every direction of the upper hemisphere.
#pragma once

#include "obscura/trace/bsdf.h"

namespace obscura {

struct LambertianBsdf {
  Rgb reflectance;  // albedo ρ, each in [0, 1]

  Rgb f(Vector3f wo, Vector3f wi) const;
  float pdf(Vector3f wo, Vector3f wi) const;
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const;
};

}  // namespace obscura
