// A thin dielectric wall (glTF KHR_materials_transmission without KHR_materials_volume): it
// reflects like the interface of a dielectric of index `ior` and lets the rest through without
// bending it, because entering and leaving a wall of no thickness refract by opposite angles.
// Rough walls spread the transmitted light with the same GGX lobe as the reflection, mirrored to
// the other side (the glTF specification's thin-walled BTDF). Both faces behave alike; values
// are for radiance, with no 1/η² (the light leaves into the medium it came from).
#pragma once

#include "obscura/trace/bsdf.h"
#include "obscura/trace/ggx.h"

namespace obscura {

struct ThinDielectricBsdf {
  ThinDielectricBsdf(float ior, float alpha, Rgb transmittance = Rgb(1.f));

  Rgb f(Vector3f wo, Vector3f wi) const;
  float pdf(Vector3f wo, Vector3f wi) const;
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const;
  bool is_delta() const { return distribution.effectively_smooth(); }

  float ior;
  Ggx distribution;
  Rgb transmittance;  // tint of the light let through
};

}  // namespace obscura
