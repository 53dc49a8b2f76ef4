// The glTF 2.0 metallic-roughness material (glTF specification, Appendix B), with
// KHR_materials_specular and KHR_materials_ior:
//   metal      = F_metal · specular,        F_metal = base + (1 − base)(1 − |v·h|)⁵
//   dielectric = (1 − s·F_d(n·wo))(1 − s·F_d(n·wi)) · base/π + s · F_d · specular,
//                F_d = f0 + (1 − f0)(1 − |v·h|)⁵,  f0 = min(((η−1)/(η+1))² · specular_color, 1)
//   f          = mix(dielectric, metal, metallic)
// where specular = D·G / (4 cosθo cosθi) is the GGX lobe with α = roughness² and s the
// KHR_materials_specular strength. The diffuse weight departs from the specification's
// 1 − s·max(F_d(v·h)), which is not energy conserving at grazing angles (see the .cpp).
#pragma once

#include "obscura/trace/bsdf.h"
#include "obscura/trace/ggx.h"

namespace obscura {

struct MetallicRoughnessParameters {
  Rgb base_color{1.f};
  float metallic = 1, roughness = 1;
  float specular = 1;  // KHR_materials_specular strength, in [0, 1]
  Rgb specular_color{1.f};
  float ior = 1.5f;
};

struct MetallicRoughnessBsdf {
  explicit MetallicRoughnessBsdf(const MetallicRoughnessParameters& p);

  Rgb f(Vector3f wo, Vector3f wi) const;
  float pdf(Vector3f wo, Vector3f wi) const;
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const;

  MetallicRoughnessParameters params;
  Rgb dielectric_f0;
  Ggx distribution;
  float specular_probability;  // of sampling the GGX lobe rather than the diffuse one
};

}  // namespace obscura
