#include "obscura/raster/surface_material.h"

#include <algorithm>
#include <variant>

#include "obscura/shading/material_point.h"
#include "obscura/shading/phong_albedo.h"

namespace obscura::raster {

namespace {

float ggx_alpha(float roughness) {
  float r = std::clamp(roughness, 0.f, 1.f);
  return r * r;
}

Rgb min(Rgb a, float b) {
  return {std::min(a.r, b), std::min(a.g, b), std::min(a.b, b)};
}

// The glTF models' parameters at a point, as the reflection formulas take them.
void set_metallic_roughness(SurfacePoint& p, const shading::MetallicRoughnessPoint& mr,
                            bool layered) {
  p.base = mr.base_color;
  p.metallic = mr.metallic;
  // The tracer's floor on α (twice its mirror threshold) keeps D finite in float.
  p.alpha = std::max(ggx_alpha(mr.roughness), 2e-3f);
  p.specular_strength = mr.specular;
  p.ior = mr.ior;
  const float f0 = ((mr.ior - 1) / (mr.ior + 1)) * ((mr.ior - 1) / (mr.ior + 1));
  p.specular = min(mr.specular_color * f0, 1.f);
  p.transmission = std::clamp(mr.transmission, 0.f, 1.f);
  // Layers only where the model has them (not over transmission, as in the tracer).
  p.clearcoat = layered ? std::clamp(mr.clearcoat, 0.f, 1.f) : 0.f;
  p.coat_alpha = std::max(ggx_alpha(layered ? mr.clearcoat_roughness : 0.f), 2e-3f);
  p.sheen = layered ? mr.sheen_color : Rgb();
  p.sheen_alpha = shading::sheen_alpha(layered ? mr.sheen_roughness : 0.f);
}

// The material at a point whose textures `lookup` reads (shading::TextureLookup).
template <shading::TextureLookup L>
SurfacePoint point_with(const SurfaceMaterial& m, Rgb vertex_color, const L& lookup) {
  SurfacePoint p{};
  p.model = m.model;
  p.specular = m.specular;
  p.shininess = m.shininess;
  p.alpha = m.alpha;
  p.ior = m.ior;
  p.eta = m.eta, p.k = m.k, p.transmittance = m.transmittance;
  p.multiple_scattering = m.multiple_scattering;
  p.occlusion = lookup.color(m.occlusion_texture).r;
  switch (m.model) {
    case SurfaceModel::kMetallicRoughness:
    case SurfaceModel::kLayeredMetallicRoughness:
      set_metallic_roughness(
          p, shading::metallic_roughness_at(m.metallic_roughness, vertex_color, lookup),
          m.model == SurfaceModel::kLayeredMetallicRoughness);
      break;
    case SurfaceModel::kPhong:
    case SurfaceModel::kBlinnPhong:
      p.base = shading::base_color_at(m.base, m.base_texture, vertex_color, lookup);
      shading::conserve_energy(p.base, p.specular);
      p.lobe_normalization = m.model == SurfaceModel::kPhong
                                 ? shading::phong_lobe_normalization(p.shininess)
                                 : shading::blinn_phong_lobe_normalization(p.shininess);
      break;
    default:
      p.base = shading::base_color_at(m.base, m.base_texture, vertex_color, lookup);
      break;
  }
  return p;
}

}  // namespace

SurfaceMaterial compile_material(const Material& material, const TextureTable* textures) {
  SurfaceMaterial s;
  s.textures = textures;
  s.emission = material.emission;
  s.emission_texture = material.emission_texture;
  s.normal_texture = material.normal_texture;
  s.normal_scale = material.normal_scale;
  s.double_sided = material.double_sided;
  struct Visitor {
    SurfaceMaterial& s;
    void operator()(const DiffuseMaterial& m) const {
      s.model = SurfaceModel::kLambert;
      s.base = m.reflectance;
      s.base_texture = m.reflectance_texture;
    }
    void operator()(const obscura::PhongMaterial& m) const {
      s.model = m.blinn ? SurfaceModel::kBlinnPhong : SurfaceModel::kPhong;
      s.base = m.diffuse;
      s.specular = m.specular;
      s.shininess = std::max(0.f, m.shininess);
      s.base_texture = m.diffuse_texture;
    }
    void operator()(const ConductorMaterial& m) const {
      s.model = SurfaceModel::kConductor;
      s.eta = m.eta, s.k = m.k;
      s.alpha = std::max(ggx_alpha(m.roughness), kMinHighlightAlpha);
      s.multiple_scattering =
          shading::multiple_scattering_color(shading::fresnel_average([&](float mu) {
                                               return shading::fresnel_conductor(mu, m.eta, m.k);
                                             }),
                                             s.alpha);
    }
    void operator()(const DielectricMaterial& m) const {
      s.model = SurfaceModel::kDielectric;
      s.ior = m.ior;
      s.transmittance = m.transmittance;
      s.alpha = std::max(ggx_alpha(m.roughness), kMinHighlightAlpha);
    }
    void operator()(const MetallicRoughnessMaterial& m) const {
      s.base = m.base_color;
      s.base_texture = m.base_color_texture;
      s.occlusion_texture = m.occlusion_texture;
      s.metallic_roughness = m;
      if (m.unlit) {
        s.model = SurfaceModel::kUnlit;
        return;
      }
      // KHR_materials_specular with a zero specular: a plain Lambertian surface (as the tracer).
      s.model = m.purely_diffuse() ? SurfaceModel::kLambert : SurfaceModel::kMetallicRoughness;
      // KHR_materials_clearcoat and _sheen (as the tracer: not over transmission).
      if (s.model == SurfaceModel::kMetallicRoughness && m.transmission == 0 &&
          (m.has_clearcoat() || m.has_sheen()))
        s.model = SurfaceModel::kLayeredMetallicRoughness;
    }
    void operator()(const EmissiveMaterial&) const { s.model = SurfaceModel::kBlack; }
  };
  std::visit(Visitor{s}, material.model);
  if (const auto* mr = std::get_if<MetallicRoughnessMaterial>(&material.model)) {
    s.alpha_mode = material.alpha_mode;
    s.alpha_cutoff = material.alpha_cutoff;
    s.base_alpha = mr->alpha;
    s.alpha_texture = mr->base_color_texture;
  }
  return s;
}

SurfacePoint surface_point_untextured(const SurfaceMaterial& m, Rgb vertex_color) {
  return point_with(m, vertex_color, shading::NoTextures{});
}

SurfacePoint surface_point(const SurfaceMaterial& m, const FragmentUvs& uvs, Rgb vertex_color) {
  return point_with(m, vertex_color, FragmentTextures(m.textures, m.filter, uvs));
}

namespace {

// The directional albedo of the GGX lobe with Schlick's Fresnel of normal reflectance f0 (per
// channel): f0·E(μ) + (1 − f0)·E₅(μ), linear in f0.
Rgb ggx_schlick_albedo(Rgb f0, float mu, float alpha) {
  const float e = shading::ggx_albedo(mu, alpha), e5 = shading::ggx_schlick_albedo(0, mu, alpha);
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
      r.specular = s.specular * shading::phong_lobe_albedo(mu, s.shininess,
                                                           s.model == SurfaceModel::kBlinnPhong);
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
      const float left = 1 - s.specular_strength * shading::ggx_schlick_albedo(f0, mu, s.alpha);
      const Rgb metal =
          ggx_schlick_albedo(s.base, mu, s.alpha) +
          shading::multiple_scattering_color(shading::schlick_average(s.base), s.alpha) *
              (1 - shading::ggx_albedo(mu, s.alpha));
      r.diffuse = s.base * (left * (1 - s.metallic));
      r.specular =
          ggx_schlick_albedo(s.specular, mu, s.alpha) * (s.specular_strength * (1 - s.metallic)) +
          metal * s.metallic;
      r.roughness = std::sqrt(s.alpha);
      if (s.model == SurfaceModel::kMetallicRoughness) break;
      // The layers as for lights, their albedos at the shading normal's n·v: the sheen (bounded
      // at 1, broad, so lit by the irradiance) takes its share from what lies beneath, and the
      // coat from both, reflecting the surround itself at its own roughness.
      const float sheen_max = std::max({s.sheen.r, s.sheen.g, s.sheen.b});
      if (sheen_max > 0) {
        const float e = std::min(shading::sheen_albedo(mu, s.sheen_alpha), 1.f);
        r.diffuse = r.diffuse * (1 - sheen_max * e) + s.sheen * e;
        r.specular = r.specular * (1 - sheen_max * e);
      }
      if (s.clearcoat > 0) {
        const float e = s.clearcoat * shading::ggx_schlick_albedo(0.04f, mu, s.coat_alpha);
        r.diffuse = r.diffuse * (1 - e);
        r.specular = r.specular * (1 - e);
        r.coat = Rgb(e);
        r.coat_roughness = std::sqrt(s.coat_alpha);
      }
      break;
    }
    case SurfaceModel::kConductor:
      r.specular = ggx_schlick_albedo(shading::fresnel_conductor(1.f, s.eta, s.k), mu, s.alpha) +
                   s.multiple_scattering * (1 - shading::ggx_albedo(mu, s.alpha));
      r.roughness = std::sqrt(s.alpha);
      break;
    case SurfaceModel::kDielectric: {
      // Reflected surround plus the surround seen through the glass.
      const float f0 = ((s.ior - 1) / (s.ior + 1)) * ((s.ior - 1) / (s.ior + 1));
      const float reflected = f0 * shading::ggx_albedo(mu, s.alpha) +
                              (1 - f0) * shading::ggx_schlick_albedo(0, mu, s.alpha);
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

}  // namespace obscura::raster
