// The glTF 2.0 metallic-roughness material (glTF specification, Appendix B), with
// KHR_materials_specular and KHR_materials_ior:
//   metal      = F_metal · specular + F_ms · f_ms,   F_metal = base + (1 − base)(1 − |v·h|)⁵
//   dielectric = (1 − s·E_d(μo))(1 − s·E_d(μi)) / (1 − s·E_d,avg) · base/π + s · F_d · specular,
//                F_d = f0 + (1 − f0)(1 − |v·h|)⁵,  f0 = min(((η−1)/(η+1))² · specular_color, 1)
//   f          = mix(dielectric, metal, metallic)
// where specular = D·G / (4 cosθo cosθi) is the GGX lobe with α = roughness², s the
// KHR_materials_specular strength, f_ms and F_ms Kulla–Conty's multiple-scattering lobe and its
// colour, and E_d the directional albedo of s·F_d·specular (shading/ggx_energy.h). Two
// departures from the specification, both so that a white material in a white furnace
// reflects exactly what arrives (the Khronos furnace test): the metal's multiple scattering,
// and a diffuse weight that takes exactly the energy the specular layer leaves instead of the
// specification's 1 − s·max(F_d(v·h)), which reflects more than arrives at grazing angles.
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
  Rgb metal_multiple_scattering;  // F_ms for the metal's Fresnel
  float diffuse_average_left;     // 1 − s·E_d,avg: what the specular layer leaves on average
  float specular_probability;     // of sampling the GGX lobe rather than the diffuse one
};

}  // namespace obscura
