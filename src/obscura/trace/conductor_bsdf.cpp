#include "obscura/trace/conductor_bsdf.h"

#include <algorithm>

#include "obscura/math/sampling.h"
#include "obscura/shading/fresnel.h"
#include "obscura/shading/ggx.h"
#include "obscura/shading/ggx_energy.h"

namespace obscura {

ConductorBsdf::ConductorBsdf(Rgb eta_, Rgb k_, float alpha)
    : eta(eta_), k(k_), distribution(alpha) {
  if (is_delta()) return;
  multiple_scattering = shading::multiple_scattering_color(
      shading::fresnel_average([&](float mu) { return shading::fresnel_conductor(mu, eta, k); }),
      alpha);
  // The share of the multiple-scattering lobe in what is reflected along the normal.
  float single = shading::ggx_albedo(1, alpha);
  float multiple = luminance(multiple_scattering) * (1 - single);
  multiple_probability = std::clamp(multiple / std::max(single + multiple, 1e-6f), 0.02f, 0.5f);
}

Rgb ConductorBsdf::f(Vector3f wo, Vector3f wi) const {
  if (is_delta() || wo.z <= 0 || wi.z <= 0) return {};
  Vector3f wm = wo + wi;
  if (length_squared(wm) == 0) return {};
  wm = normalize(wm);
  Rgb fresnel = shading::fresnel_conductor(dot(wo, wm), eta, k);
  return fresnel * (shading::ggx_specular(wo.z, wi.z, wm.z, distribution.alpha())) +
         multiple_scattering * shading::ggx_multiple_scattering(wo.z, wi.z, distribution.alpha());
}

float ConductorBsdf::pdf(Vector3f wo, Vector3f wi) const {
  if (is_delta() || wo.z <= 0 || wi.z <= 0) return 0;
  Vector3f wm = wo + wi;
  if (length_squared(wm) == 0) return 0;
  wm = normalize(wm);
  // The reflection's Jacobian dωm/dωi = 1 / (4 |wo·wm|).
  float specular = distribution.visible_D(wo, wm) / (4 * dot(wo, wm));
  return (1 - multiple_probability) * specular + multiple_probability * cosine_hemisphere_pdf(wi.z);
}

std::optional<BsdfSample> ConductorBsdf::sample(Vector3f wo, float uc, Point2f u) const {
  if (wo.z <= 0) return std::nullopt;
  if (is_delta()) {
    Vector3f wi(-wo.x, -wo.y, wo.z);
    return BsdfSample{
        .f = shading::fresnel_conductor(wo.z, eta, k) / wi.z, .wi = wi, .pdf = 1, .is_delta = true};
  }
  Vector3f wi = uc < multiple_probability ? sample_cosine_hemisphere(u)
                                          : reflect(wo, distribution.sample_visible_normal(wo, u));
  if (wi.z <= 0) return std::nullopt;
  float p = pdf(wo, wi);
  if (p <= 0) return std::nullopt;
  return BsdfSample{.f = f(wo, wi), .wi = wi, .pdf = p};
}

}  // namespace obscura
