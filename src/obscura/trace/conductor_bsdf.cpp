#include "obscura/trace/conductor_bsdf.h"

#include "obscura/trace/fresnel.h"

namespace obscura {

ConductorBsdf::ConductorBsdf(Rgb eta_, Rgb k_, float alpha)
    : eta(eta_), k(k_), distribution(alpha) {}

Rgb ConductorBsdf::f(Vector3f wo, Vector3f wi) const {
  if (is_delta() || wo.z <= 0 || wi.z <= 0) return {};
  Vector3f wm = wo + wi;
  if (length_squared(wm) == 0) return {};
  wm = normalize(wm);
  Rgb fresnel = fresnel_conductor(dot(wo, wm), eta, k);
  return fresnel * (distribution.D(wm) * distribution.G(wo, wi) / (4 * wo.z * wi.z));
}

float ConductorBsdf::pdf(Vector3f wo, Vector3f wi) const {
  if (is_delta() || wo.z <= 0 || wi.z <= 0) return 0;
  Vector3f wm = wo + wi;
  if (length_squared(wm) == 0) return 0;
  wm = normalize(wm);
  // The reflection's Jacobian dωm/dωi = 1 / (4 |wo·wm|).
  return distribution.visible_D(wo, wm) / (4 * dot(wo, wm));
}

std::optional<BsdfSample> ConductorBsdf::sample(Vector3f wo, float /*uc*/, Point2f u) const {
  if (wo.z <= 0) return std::nullopt;
  if (is_delta()) {
    Vector3f wi(-wo.x, -wo.y, wo.z);
    return BsdfSample{
        .f = fresnel_conductor(wo.z, eta, k) / wi.z, .wi = wi, .pdf = 1, .is_delta = true};
  }
  Vector3f wm = distribution.sample_visible_normal(wo, u);
  Vector3f wi = reflect(wo, wm);
  if (wi.z <= 0) return std::nullopt;
  float p = pdf(wo, wi);
  if (p <= 0) return std::nullopt;
  return BsdfSample{.f = f(wo, wi), .wi = wi, .pdf = p};
}

}  // namespace obscura
