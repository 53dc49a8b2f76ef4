#include "obscura/trace/metallic_roughness_bsdf.h"

#include <algorithm>

#include "obscura/math/sampling.h"
#include "obscura/trace/fresnel.h"

namespace obscura {

namespace {

Rgb min(Rgb a, float b) {
  return {std::min(a.r, b), std::min(a.g, b), std::min(a.b, b)};
}
Rgb lerp(float t, Rgb a, Rgb b) {
  return a * (1 - t) + b * t;
}

}  // namespace

MetallicRoughnessBsdf::MetallicRoughnessBsdf(const MetallicRoughnessParameters& p)
    : params(p),
      dielectric_f0(min(p.specular_color * fresnel_f0(p.ior), 1.f)),
      distribution(std::max(Ggx::alpha_from_roughness(p.roughness), 2 * Ggx::kSmoothAlpha)) {
  // Sample each lobe in proportion to an estimate of its reflectance seen from the normal.
  Rgb spec_weight = lerp(params.metallic, dielectric_f0 * params.specular, params.base_color);
  float diffuse_weight = (1 - params.metallic) * luminance(params.base_color) *
                         (1 - params.specular * dielectric_f0.max_component());
  float ws = luminance(spec_weight);
  specular_probability = ws + diffuse_weight > 0 ? ws / (ws + diffuse_weight) : 1.f;
  // Grazing Fresnel raises the specular share well above its normal-incidence estimate.
  if (params.specular > 0 || params.metallic > 0)
    specular_probability = std::clamp(specular_probability, 0.1f, 1.f);
}

Rgb MetallicRoughnessBsdf::f(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  Vector3f h = normalize(wo + wi);
  float v_h = dot(wo, h);
  float specular_lobe = distribution.D(h) * distribution.G(wo, wi) / (4 * wo.z * wi.z);
  Rgb f_metal = fresnel_schlick(params.base_color, v_h);
  Rgb f_dielectric = fresnel_schlick(dielectric_f0, v_h);
  // The specification weights the diffuse lobe by 1 − F(v·h), which reflects up to a third more
  // light than arrives at grazing angles. Weighting it by what the specular layer leaves on the
  // way in and on the way out, (1 − F(n·wo))(1 − F(n·wi)), keeps the total ≤ 1 and reciprocal
  // and equals the specification at normal incidence up to F0² (0.0016 for glTF's default).
  float s = params.specular;
  float f0 = dielectric_f0.max_component();
  float diffuse_weight = (1 - s * fresnel_schlick(f0, wo.z)) * (1 - s * fresnel_schlick(f0, wi.z));
  Rgb dielectric =
      params.base_color * (diffuse_weight * kInvPi) + f_dielectric * (s * specular_lobe);
  Rgb metal = f_metal * specular_lobe;
  return lerp(params.metallic, dielectric, metal);
}

float MetallicRoughnessBsdf::pdf(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  Vector3f h = normalize(wo + wi);
  float specular_pdf = distribution.visible_D(wo, h) / (4 * dot(wo, h));
  return specular_probability * specular_pdf +
         (1 - specular_probability) * cosine_hemisphere_pdf(wi.z);
}

std::optional<BsdfSample> MetallicRoughnessBsdf::sample(Vector3f wo, float uc, Point2f u) const {
  if (wo.z <= 0) return std::nullopt;
  Vector3f wi = uc < specular_probability ? reflect(wo, distribution.sample_visible_normal(wo, u))
                                          : sample_cosine_hemisphere(u);
  if (wi.z <= 0) return std::nullopt;
  float p = pdf(wo, wi);
  if (p <= 0) return std::nullopt;
  return BsdfSample{.f = f(wo, wi), .wi = wi, .pdf = p};
}

}  // namespace obscura
