// The glTF metallic-roughness material with KHR_materials_transmission. The specification mixes
//   f = mix(dielectric, metal, metallic),
//   dielectric = fresnel_mix(specular_brdf, mix(diffuse_brdf, specular_btdf · base, T)),
// and since fresnel_mix(s, mix(d, t, T)) = mix(fresnel_mix(s, d), fresnel_mix(s, t), T), that is
//   f = (1 − w) · opaque + w · glass,   w = (1 − metallic) · T,
// with `opaque` the MetallicRoughnessBsdf of metallic' = metallic / (1 − w) and `glass` a
// dielectric interface whose refracted light is tinted by the base colour: a refracting one
// (DielectricBsdf) at the boundary of a closed volume (KHR_materials_volume), a thin wall
// (ThinDielectricBsdf) otherwise. The glass uses the exact dielectric Fresnel (the opaque part
// keeps the specification's Schlick) and ignores KHR_materials_specular.
//
// The frame's +Z is the front (outside) face, as for every transmissive BSDF; the opaque part
// reflects on whichever side wo is.
#pragma once

#include "obscura/trace/dielectric_bsdf.h"
#include "obscura/trace/metallic_roughness_bsdf.h"
#include "obscura/trace/thin_dielectric_bsdf.h"

namespace obscura {

struct TransmissiveMetallicRoughnessBsdf {
  TransmissiveMetallicRoughnessBsdf(const MetallicRoughnessParameters& p, float transmission,
                                    bool volume);

  Rgb f(Vector3f wo, Vector3f wi) const;
  float pdf(Vector3f wo, Vector3f wi) const;
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const;
  bool is_delta() const { return glass_weight >= 1 && glass_is_delta(); }

  Rgb base_color() const { return opaque.params.base_color; }

  MetallicRoughnessBsdf opaque;
  bool volume;
  DielectricBsdf refracting;  // volume
  ThinDielectricBsdf thin;    // no volume
  float glass_weight;         // w = (1 − metallic) · transmission

 private:
  bool glass_is_delta() const { return volume ? refracting.is_delta() : thin.is_delta(); }
  Rgb opaque_f(Vector3f wo, Vector3f wi) const;
  float opaque_pdf(Vector3f wo, Vector3f wi) const;
  Rgb glass_f(Vector3f wo, Vector3f wi) const {
    return volume ? refracting.f(wo, wi) : thin.f(wo, wi);
  }
  float glass_pdf(Vector3f wo, Vector3f wi) const {
    return volume ? refracting.pdf(wo, wi) : thin.pdf(wo, wi);
  }
};

}  // namespace obscura
