#include "obscura/trace/dielectric_bsdf.h"

#include "obscura/shading/fresnel.h"

namespace obscura {

DielectricBsdf::DielectricBsdf(float ior_, float alpha, Rgb transmittance_)
    : ior(ior_), distribution(alpha), transmittance(transmittance_) {}

bool DielectricBsdf::half_vector(Vector3f wo, Vector3f wi, Vector3f* wm,
                                 float* eta_relative) const {
  float cos_o = wo.z, cos_i = wi.z;
  if (cos_o == 0 || cos_i == 0) return false;
  bool reflection = cos_o * cos_i > 0;
  *eta_relative = reflection ? 1.f : (cos_o > 0 ? ior : 1 / ior);
  Vector3f m = wi * *eta_relative + wo;
  if (length_squared(m) == 0) return false;
  m = normalize(m);
  if (m.z < 0) m = -m;
  // Both directions must lie on the microfacet's sides that the geometry allows.
  if (dot(m, wi) * cos_i < 0 || dot(m, wo) * cos_o < 0) return false;
  *wm = m;
  return true;
}

Rgb DielectricBsdf::f(Vector3f wo, Vector3f wi) const {
  if (is_delta()) return {};
  Vector3f wm;
  float etap;
  if (!half_vector(wo, wi, &wm, &etap)) return {};
  float fresnel = shading::fresnel_dielectric(dot(wo, wm), ior);
  float d = distribution.D(wm), g = distribution.G(wo, wi);
  if (same_hemisphere(wo, wi)) return Rgb(d * g * fresnel / std::abs(4 * wo.z * wi.z));
  float denom = dot(wi, wm) + dot(wo, wm) / etap;
  denom = denom * denom * wi.z * wo.z;
  float ft = d * (1 - fresnel) * g * std::abs(dot(wi, wm) * dot(wo, wm) / denom);
  return transmittance * (ft / (etap * etap));
}

float DielectricBsdf::pdf(Vector3f wo, Vector3f wi) const {
  if (is_delta()) return 0;
  Vector3f wm;
  float etap;
  if (!half_vector(wo, wi, &wm, &etap)) return 0;
  float r = shading::fresnel_dielectric(dot(wo, wm), ior), t = 1 - r;
  if (same_hemisphere(wo, wi))
    return distribution.visible_D(wo, wm) / (4 * std::abs(dot(wo, wm))) * r;
  float denom = dot(wi, wm) + dot(wo, wm) / etap;
  float dwm_dwi = std::abs(dot(wi, wm)) / (denom * denom);
  return distribution.visible_D(wo, wm) * dwm_dwi * t;
}

std::optional<BsdfSample> DielectricBsdf::sample(Vector3f wo, float uc, Point2f u) const {
  if (wo.z == 0) return std::nullopt;
  if (is_delta()) {
    // Reflect with probability R, refract otherwise, about the macro normal.
    float r = shading::fresnel_dielectric(wo.z, ior), t = 1 - r;
    if (uc < r) {
      Vector3f wi(-wo.x, -wo.y, wo.z);
      return BsdfSample{.f = Rgb(r / abs_cos_theta(wi)), .wi = wi, .pdf = r, .is_delta = true};
    }
    Vector3f wi;
    float etap;
    if (!refract(wo, {0, 0, 1}, ior, &wi, &etap)) return std::nullopt;
    return BsdfSample{.f = transmittance * (t / (abs_cos_theta(wi) * etap * etap)),
                      .wi = wi,
                      .pdf = t,
                      .is_delta = true,
                      .is_transmission = true,
                      .eta = etap};
  }
  Vector3f wm = distribution.sample_visible_normal(wo, u);
  float r = shading::fresnel_dielectric(dot(wo, wm), ior);
  Vector3f wi;
  bool transmission = false;
  float etap = 1;
  if (uc < r) {
    wi = reflect(wo, wm);
    if (!same_hemisphere(wo, wi)) return std::nullopt;
  } else {
    if (!refract(wo, wm, ior, &wi, &etap) || same_hemisphere(wo, wi) || wi.z == 0)
      return std::nullopt;
    transmission = true;
  }
  float p = pdf(wo, wi);
  if (p <= 0) return std::nullopt;
  return BsdfSample{.f = f(wo, wi),
                    .wi = wi,
                    .pdf = p,
                    .is_transmission = transmission,
                    .eta = transmission ? etap : 1.f};
}

}  // namespace obscura
