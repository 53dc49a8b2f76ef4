// Glass, water: an interface between two dielectrics that reflects and refracts. Smooth (delta
// reflection and refraction, chosen in proportion to Fresnel) or rough (GGX microfacets, Walter
// et al. 2007, with visible-normal sampling). The frame's +Z is the outside; `ior` is the index
// inside relative to outside. Values are for radiance: transmitted radiance is scaled by 1/η²
// (light is compressed into a narrower cone when it enters a denser medium).
#pragma once

#include "obscura/trace/bsdf.h"
#include "obscura/trace/ggx.h"

namespace obscura {

struct DielectricBsdf {
  DielectricBsdf(float ior, float alpha, Rgb transmittance = Rgb(1.f));

  Rgb f(Vector3f wo, Vector3f wi) const;
  float pdf(Vector3f wo, Vector3f wi) const;
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const;
  bool is_delta() const { return distribution.effectively_smooth() || ior == 1; }

  float ior;
  Ggx distribution;
  Rgb transmittance;  // tint of refracted light

 private:
  // The generalized half vector of (wo, wi), on the +Z side, and the index ratio crossed;
  // false for configurations microfacets cannot produce.
  bool half_vector(Vector3f wo, Vector3f wi, Vector3f* wm, float* eta_relative) const;
};

}  // namespace obscura
