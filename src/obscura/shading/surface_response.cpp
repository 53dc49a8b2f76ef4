#include "obscura/shading/surface_response.h"

#include "obscura/shading/phong_albedo.h"

namespace obscura::shading {

namespace {

// The directional albedo of the GGX lobe with Schlick's Fresnel of normal reflectance f0 (per
// channel): f0·E(μ) + (1 − f0)·E₅(μ), linear in f0.
Rgb ggx_schlick_albedo_rgb(Rgb f0, float mu, float alpha) {
  const float e = ggx_albedo(mu, alpha), e5 = ggx_schlick_albedo(0, mu, alpha);
  return f0 * e + (Rgb(1.f) - f0) * e5;
}

}  // namespace

EnvironmentResponse environment_response(const SurfacePoint& s, float n_dot_v) {
  EnvironmentResponse r;
  const float mu = std::clamp(n_dot_v, 1e-4f, 1.f);
  switch (s.model) {
    case SurfaceModel::kBlack:
    case SurfaceModel::kUnlit:
      return r;
    case SurfaceModel::kLambert:
      r.diffuse = s.base;
      break;
    case SurfaceModel::kPhong:
    case SurfaceModel::kBlinnPhong:
      // A normalized lobe reflects k_s of a uniform surround at normal incidence, less away
      // from it (the lobe follows the mirror direction, whose cosine is n·v): the tracer's BSDF
      // integrated (shading/phong_albedo.h).
      r.diffuse = s.base;
      r.specular =
          s.specular * phong_lobe_albedo(mu, s.shininess, s.model == SurfaceModel::kBlinnPhong);
      // The prefilter's GGX width: Beckmann's α = √(2 / (n + 2)) for Blinn's half-vector lobe
      // (Walter et al. 2007), whose angle is half the reflection lobe's, so a Phong lobe of
      // exponent n is as wide as a Blinn-Phong one of about 4n.
      r.roughness = std::sqrt(
          std::sqrt(2 / ((s.model == SurfaceModel::kPhong ? 4 * s.shininess : s.shininess) + 2)));
      break;
    case SurfaceModel::kMetallicRoughness:
    case SurfaceModel::kLayeredMetallicRoughness: {
      // The tracer's diffuse weight (1 − k·E_F(μ_v))(1 − k·E_F(μ_l)) / (1 − k·E_F,avg) reflects
      // exactly 1 − k·E_F(μ_v) of a uniform surround.
      const float f0 = std::max({s.specular.r, s.specular.g, s.specular.b});
      const float left = 1 - s.specular_strength * ggx_schlick_albedo(f0, mu, s.alpha);
      const Rgb metal = ggx_schlick_albedo_rgb(s.base, mu, s.alpha) +
                        multiple_scattering_color(schlick_average(s.base), s.alpha) *
                            (1 - ggx_albedo(mu, s.alpha));
      r.diffuse = s.base * (left * (1 - s.metallic));
      r.specular = ggx_schlick_albedo_rgb(s.specular, mu, s.alpha) *
                       (s.specular_strength * (1 - s.metallic)) +
                   metal * s.metallic;
      r.roughness = std::sqrt(s.alpha);
      if (s.model == SurfaceModel::kMetallicRoughness) break;
      // The layers as for lights, their albedos at the shading normal's n·v: the sheen (bounded
      // at 1, broad, so lit by the irradiance) takes its share from what lies beneath, and the
      // coat from both, reflecting the surround itself at its own roughness.
      const float sheen_max = std::max({s.sheen.r, s.sheen.g, s.sheen.b});
      if (sheen_max > 0) {
        const float e = std::min(sheen_albedo(mu, s.sheen_alpha), 1.f);
        r.diffuse = r.diffuse * (1 - sheen_max * e) + s.sheen * e;
        r.specular = r.specular * (1 - sheen_max * e);
      }
      if (s.clearcoat > 0) {
        const float e = s.clearcoat * ggx_schlick_albedo(0.04f, mu, s.coat_alpha);
        r.diffuse = r.diffuse * (1 - e);
        r.specular = r.specular * (1 - e);
        r.coat = Rgb(e);
        r.coat_roughness = std::sqrt(s.coat_alpha);
      }
      break;
    }
    case SurfaceModel::kConductor:
      r.specular = ggx_schlick_albedo_rgb(fresnel_conductor(1.f, s.eta, s.k), mu, s.alpha) +
                   s.multiple_scattering * (1 - ggx_albedo(mu, s.alpha));
      r.roughness = std::sqrt(s.alpha);
      break;
    case SurfaceModel::kDielectric: {
      // Reflected surround plus the surround seen through the glass.
      const float f0 = ((s.ior - 1) / (s.ior + 1)) * ((s.ior - 1) / (s.ior + 1));
      const float reflected =
          f0 * ggx_albedo(mu, s.alpha) + (1 - f0) * ggx_schlick_albedo(0, mu, s.alpha);
      r.specular = Rgb(reflected);
      r.transmitted = s.transmittance * (1 - reflected);
      r.roughness = std::sqrt(s.alpha);
      break;
    }
  }
  r.diffuse = r.diffuse * s.occlusion;
  r.specular = r.specular * s.occlusion;
  r.transmitted = r.transmitted * s.occlusion;
  r.coat = r.coat * s.occlusion;
  return r;
}

Rgb ambient_reflectance(const SurfacePoint& s, float n_dot_v) {
  EnvironmentResponse r = environment_response(s, n_dot_v);
  return r.diffuse + r.specular + r.transmitted + r.coat;
}

}  // namespace obscura::shading
