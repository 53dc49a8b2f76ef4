#include "obscura/trace/phong_bsdf.h"

#include <algorithm>
#include <cmath>

#include "obscura/math/sampling.h"
#include "obscura/shading/phong_lobe.h"

namespace obscura {

namespace {

// A direction around `axis` with density (n+1)/2π · cos^n of the angle to it.
Vector3f sample_power_cosine(Vector3f axis, float n, Point2f u) {
  float cos_a = std::pow(u.x, 1 / (n + 1));
  float sin_a = std::sqrt(std::max(0.f, 1 - cos_a * cos_a));
  float phi = 2 * kPi * u.y;
  ShadingFrame frame = ShadingFrame::from_normal(axis);
  return frame.to_world({sin_a * std::cos(phi), sin_a * std::sin(phi), cos_a});
}

float power_cosine_pdf(float cos_a, float n) {
  return cos_a > 0 ? (n + 1) * (0.5f * kInvPi) * std::pow(cos_a, n) : 0.f;
}

}  // namespace

PhongBsdf::PhongBsdf(Rgb diffuse_, Rgb specular_, float shininess_, bool blinn_)
    : diffuse(diffuse_), specular(specular_), shininess(std::max(0.f, shininess_)), blinn(blinn_) {
  shading::conserve_energy(diffuse, specular);
  normalization = blinn ? shading::blinn_phong_lobe_normalization(shininess)
                        : shading::phong_lobe_normalization(shininess);
  float wd = luminance(diffuse), ws = luminance(specular);
  specular_probability = wd + ws > 0 ? ws / (wd + ws) : 0.f;
}

float PhongBsdf::lobe(Vector3f wo, Vector3f wi) const {
  float c = blinn ? normalize(wo + wi).z : dot(Vector3f(-wo.x, -wo.y, wo.z), wi);
  return c > 0 ? std::pow(c, shininess) : 0.f;
}

Rgb PhongBsdf::f(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  return diffuse * kInvPi + specular * (normalization * lobe(wo, wi));
}

float PhongBsdf::lobe_pdf(Vector3f wo, Vector3f wi) const {
  if (!blinn) return power_cosine_pdf(dot(Vector3f(-wo.x, -wo.y, wo.z), wi), shininess);
  Vector3f h = normalize(wo + wi);
  float wo_h = dot(wo, h);
  return wo_h > 0 ? power_cosine_pdf(h.z, shininess) / (4 * wo_h) : 0.f;
}

float PhongBsdf::pdf(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  return (1 - specular_probability) * cosine_hemisphere_pdf(wi.z) +
         specular_probability * lobe_pdf(wo, wi);
}

std::optional<BsdfSample> PhongBsdf::sample(Vector3f wo, float uc, Point2f u) const {
  if (wo.z <= 0) return std::nullopt;
  Vector3f wi;
  if (uc < specular_probability) {
    if (blinn)
      wi = reflect(wo, sample_power_cosine({0, 0, 1}, shininess, u));
    else
      wi = sample_power_cosine({-wo.x, -wo.y, wo.z}, shininess, u);
  } else {
    wi = sample_cosine_hemisphere(u);
  }
  if (wi.z <= 0) return std::nullopt;
  float p = pdf(wo, wi);
  if (p <= 0) return std::nullopt;
  return BsdfSample{.f = f(wo, wi), .wi = wi, .pdf = p};
}

}  // namespace obscura
