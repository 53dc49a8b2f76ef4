#include "obscura/trace/thin_dielectric_bsdf.h"

#include "obscura/shading/fresnel.h"
#include "obscura/shading/ggx.h"

namespace obscura {

namespace {

// Both faces act alike: work on the +Z side, and mirror a transmitted direction back onto it,
// where it is the reflection lobe's direction.
Vector3f upper(Vector3f w) {
  return {w.x, w.y, std::abs(w.z)};
}

}  // namespace

ThinDielectricBsdf::ThinDielectricBsdf(float ior_, float alpha, Rgb transmittance_)
    : ior(ior_), distribution(alpha), transmittance(transmittance_) {}

Rgb ThinDielectricBsdf::f(Vector3f wo, Vector3f wi) const {
  if (is_delta() || wo.z == 0 || wi.z == 0) return {};
  Vector3f o = upper(wo), i = upper(wi);
  Vector3f h = normalize(o + i);
  float fresnel = shading::fresnel_dielectric(dot(o, h), ior);
  float lobe = shading::ggx_specular(o.z, i.z, h.z, distribution.alpha());
  if (same_hemisphere(wo, wi)) return Rgb(fresnel * lobe);
  return transmittance * ((1 - fresnel) * lobe);
}

float ThinDielectricBsdf::pdf(Vector3f wo, Vector3f wi) const {
  if (is_delta() || wo.z == 0 || wi.z == 0) return 0;
  Vector3f o = upper(wo), i = upper(wi);
  Vector3f h = normalize(o + i);
  float fresnel = shading::fresnel_dielectric(dot(o, h), ior);
  float reflection_pdf = distribution.visible_D(o, h) / (4 * dot(o, h));
  return reflection_pdf * (same_hemisphere(wo, wi) ? fresnel : 1 - fresnel);
}

std::optional<BsdfSample> ThinDielectricBsdf::sample(Vector3f wo, float uc, Point2f u) const {
  if (wo.z == 0) return std::nullopt;
  const float side = wo.z > 0 ? 1.f : -1.f;
  Vector3f o = upper(wo);
  if (is_delta()) {
    float r = shading::fresnel_dielectric(o.z, ior), t = 1 - r;
    if (uc < r)
      return BsdfSample{.f = Rgb(r / o.z), .wi = {-wo.x, -wo.y, wo.z}, .pdf = r, .is_delta = true};
    return BsdfSample{.f = transmittance * (t / o.z),
                      .wi = -wo,
                      .pdf = t,
                      .is_delta = true,
                      .is_transmission = true};
  }
  Vector3f h = distribution.sample_visible_normal(o, u);
  Vector3f i = reflect(o, h);
  if (i.z <= 0) return std::nullopt;
  bool transmission = uc >= shading::fresnel_dielectric(dot(o, h), ior);
  Vector3f wi(i.x, i.y, (transmission ? -side : side) * i.z);
  float p = pdf(wo, wi);
  if (p <= 0) return std::nullopt;
  return BsdfSample{.f = f(wo, wi), .wi = wi, .pdf = p, .is_transmission = transmission};
}

}  // namespace obscura
