#include "obscura/trace/metallic_roughness_bsdf.h"

#include <algorithm>

#include "obscura/math/sampling.h"
#include "obscura/shading/fresnel.h"
#include "obscura/shading/ggx.h"
#include "obscura/shading/ggx_energy.h"

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
      dielectric_f0(min(p.specular_color * shading::fresnel_f0(p.ior), 1.f)),
      distribution(std::max(Ggx::alpha_from_roughness(p.roughness), 2 * Ggx::kSmoothAlpha)) {
  const float alpha = distribution.alpha();
  metal_multiple_scattering =
      shading::multiple_scattering_color(shading::schlick_average(params.base_color), alpha);
  const float f0 = dielectric_f0.max_component();
  diffuse_average_left = 1 - params.specular * shading::ggx_schlick_average_albedo(f0, alpha);
  // Sample each lobe in proportion to an estimate of its reflectance seen from the normal; the
  // metal's multiple scattering is diffuse-like and drawn with the diffuse lobe.
  Rgb spec_weight = lerp(params.metallic, dielectric_f0 * params.specular, params.base_color);
  float diffuse_weight =
      (1 - params.metallic) * luminance(params.base_color) *
          (1 - params.specular * dielectric_f0.max_component()) +
      params.metallic * luminance(metal_multiple_scattering) * (1 - shading::ggx_albedo(1, alpha));
  float ws = luminance(spec_weight);
  specular_probability = ws + diffuse_weight > 0 ? ws / (ws + diffuse_weight) : 1.f;
  // Grazing Fresnel raises the specular share well above its normal-incidence estimate.
  if (params.specular > 0 || params.metallic > 0)
    specular_probability = std::clamp(specular_probability, 0.1f, 0.98f);
}

Rgb MetallicRoughnessBsdf::f(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  Vector3f h = normalize(wo + wi);
  float v_h = dot(wo, h);
  const float alpha = distribution.alpha();
  float specular_lobe = shading::ggx_specular(wo.z, wi.z, h.z, alpha);
  // What single scattering between microfacets loses, put back (shading/ggx_energy.h).
  float multiple_lobe = shading::ggx_multiple_scattering(wo.z, wi.z, alpha);
  Rgb metal = shading::fresnel_schlick(params.base_color, v_h) * specular_lobe +
              metal_multiple_scattering * multiple_lobe;
  // The specification weights the diffuse lobe by 1 − F(v·h), which reflects up to a third more
  // light than arrives at grazing angles. Here it gets exactly what the specular layer leaves,
  // on the way in and on the way out: (1 − E_s(μo)) (1 − E_s(μi)) / (1 − E_s,avg) with E_s the
  // Fresnel-weighted GGX albedo. This is reciprocal, and a white base reflects everything.
  float s = params.specular;
  float f0 = dielectric_f0.max_component();
  float left_o = 1 - s * shading::ggx_schlick_albedo(f0, wo.z, alpha);
  float left_i = 1 - s * shading::ggx_schlick_albedo(f0, wi.z, alpha);
  float diffuse_weight = diffuse_average_left > 1e-6f ? left_o * left_i / diffuse_average_left : 0;
  Rgb dielectric = params.base_color * (diffuse_weight * kInvPi) +
                   shading::fresnel_schlick(dielectric_f0, v_h) * (s * specular_lobe);
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
