#include "obscura/trace/transmissive_metallic_roughness_bsdf.h"

#include <algorithm>

namespace obscura {

namespace {

MetallicRoughnessParameters opaque_parameters(MetallicRoughnessParameters p, float w) {
  p.metallic = w < 1 ? std::min(1.f, p.metallic / (1 - w)) : p.metallic;
  return p;
}

Vector3f flip(Vector3f w) {
  return {w.x, w.y, -w.z};
}

}  // namespace

TransmissiveMetallicRoughnessBsdf::TransmissiveMetallicRoughnessBsdf(
    const MetallicRoughnessParameters& p, float transmission, bool volume_)
    : opaque(opaque_parameters(p, (1 - p.metallic) * transmission)),
      volume(volume_),
      refracting(p.ior, Ggx::alpha_from_roughness(p.roughness), p.base_color),
      thin(p.ior, Ggx::alpha_from_roughness(p.roughness), p.base_color),
      glass_weight(std::clamp((1 - p.metallic) * transmission, 0.f, 1.f)) {}

// The opaque part reflects on the viewer's side: below the surface, mirrored.
Rgb TransmissiveMetallicRoughnessBsdf::opaque_f(Vector3f wo, Vector3f wi) const {
  return wo.z >= 0 ? opaque.f(wo, wi) : opaque.f(flip(wo), flip(wi));
}
float TransmissiveMetallicRoughnessBsdf::opaque_pdf(Vector3f wo, Vector3f wi) const {
  return wo.z >= 0 ? opaque.pdf(wo, wi) : opaque.pdf(flip(wo), flip(wi));
}

Rgb TransmissiveMetallicRoughnessBsdf::f(Vector3f wo, Vector3f wi) const {
  Rgb result = glass_weight > 0 ? glass_f(wo, wi) * glass_weight : Rgb();
  if (glass_weight < 1) result += opaque_f(wo, wi) * (1 - glass_weight);
  return result;
}

float TransmissiveMetallicRoughnessBsdf::pdf(Vector3f wo, Vector3f wi) const {
  float result = glass_weight > 0 ? glass_pdf(wo, wi) * glass_weight : 0.f;
  if (glass_weight < 1) result += opaque_pdf(wo, wi) * (1 - glass_weight);
  return result;
}

std::optional<BsdfSample> TransmissiveMetallicRoughnessBsdf::sample(Vector3f wo, float uc,
                                                                    Point2f u) const {
  if (wo.z == 0) return std::nullopt;
  std::optional<BsdfSample> s;
  if (uc < glass_weight) {
    float remapped = std::min(uc / glass_weight, 0x1.fffffep-1f);
    s = volume ? refracting.sample(wo, remapped, u) : thin.sample(wo, remapped, u);
    if (s && s->is_delta) {
      // A delta lobe of the glass: chosen with probability w, and nothing else shares its
      // direction.
      s->f = s->f * glass_weight;
      s->pdf *= glass_weight;
      return s;
    }
  } else {
    float remapped = std::min((uc - glass_weight) / (1 - glass_weight), 0x1.fffffep-1f);
    const bool below = wo.z < 0;
    s = opaque.sample(below ? flip(wo) : wo, remapped, u);
    if (s && below) s->wi = flip(s->wi);
  }
  if (!s) return std::nullopt;
  // Every non-delta lobe could have produced this direction: the mixture's value and density.
  s->f = f(wo, s->wi);
  s->pdf = pdf(wo, s->wi);
  if (s->pdf <= 0) return std::nullopt;
  return s;
}

}  // namespace obscura
