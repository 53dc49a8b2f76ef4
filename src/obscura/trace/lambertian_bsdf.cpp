#include "obscura/trace/lambertian_bsdf.h"

#include "obscura/math/sampling.h"

namespace obscura {

Rgb LambertianBsdf::f(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  return reflectance * kInvPi;
}

float LambertianBsdf::pdf(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  return cosine_hemisphere_pdf(wi.z);
}

std::optional<BsdfSample> LambertianBsdf::sample(Vector3f wo, float /*uc*/, Point2f u) const {
  if (wo.z <= 0) return std::nullopt;
  Vector3f wi = sample_cosine_hemisphere(u);
  if (wi.z <= 0) return std::nullopt;
  return BsdfSample{.f = reflectance * kInvPi, .wi = wi, .pdf = cosine_hemisphere_pdf(wi.z)};
}

}  // namespace obscura
