#include "obscura/raster/surface_material.h"

#include <algorithm>
#include <variant>

namespace obscura::raster {

namespace {

const Texture* texture_of(const TextureRef& ref, const std::vector<const Texture*>& textures) {
  return ref.valid() && size_t(ref.texture) < textures.size() ? textures[ref.texture] : nullptr;
}

uint8_t uv_set_of(const TextureRef& ref) {
  return ref.uv_set == 1 ? 1 : 0;  // sets past 1 are not kept (the loader warns)
}

TextureSlot slot_of(const TextureRef& ref, const std::vector<const Texture*>& textures) {
  return {texture_of(ref, textures), ref.transform, uv_set_of(ref)};
}

float ggx_alpha(float roughness) {
  float r = std::clamp(roughness, 0.f, 1.f);
  return r * r;
}

Rgb min(Rgb a, float b) {
  return {std::min(a.r, b), std::min(a.g, b), std::min(a.b, b)};
}

}  // namespace

SurfaceMaterial compile_material(const Material& material,
                                 const std::vector<const Texture*>& textures,
                                 const std::vector<const Texture*>& alpha_textures) {
  SurfaceMaterial s;
  s.emission = material.emission;
  s.emission_texture = texture_of(material.emission_texture, textures);
  s.emission_transform = material.emission_texture.transform;
  s.emission_uv_set = uv_set_of(material.emission_texture);
  s.normal_texture = texture_of(material.normal_texture, textures);
  s.normal_transform = material.normal_texture.transform;
  s.normal_uv_set = uv_set_of(material.normal_texture);
  s.normal_scale = material.normal_scale;
  s.double_sided = material.double_sided;
  struct Visitor {
    SurfaceMaterial& s;
    const std::vector<const Texture*>& textures;
    void operator()(const DiffuseMaterial& m) const {
      s.model = SurfaceModel::kLambert;
      s.base = m.reflectance;
      s.base_texture = texture_of(m.reflectance_texture, textures);
      s.base_transform = m.reflectance_texture.transform;
      s.base_uv_set = uv_set_of(m.reflectance_texture);
    }
    void operator()(const obscura::PhongMaterial& m) const {
      s.model = m.blinn ? SurfaceModel::kBlinnPhong : SurfaceModel::kPhong;
      s.base = m.diffuse;
      s.specular = m.specular;
      s.shininess = std::max(0.f, m.shininess);
      s.base_texture = texture_of(m.diffuse_texture, textures);
      s.base_transform = m.diffuse_texture.transform;
      s.base_uv_set = uv_set_of(m.diffuse_texture);
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
      s.base_texture = texture_of(m.base_color_texture, textures);
      s.base_transform = m.base_color_texture.transform;
      s.base_uv_set = uv_set_of(m.base_color_texture);
      s.occlusion_texture = texture_of(m.occlusion_texture, textures);
      s.occlusion_transform = m.occlusion_texture.transform;
      s.occlusion_uv_set = uv_set_of(m.occlusion_texture);
      if (m.unlit) {
        s.model = SurfaceModel::kUnlit;
        return;
      }
      // KHR_materials_specular with a zero specular: a plain Lambertian surface (as the tracer).
      if (m.purely_diffuse()) {
        s.model = SurfaceModel::kLambert;
        return;
      }
      s.model = SurfaceModel::kMetallicRoughness;
      s.metallic = m.metallic, s.roughness = m.roughness;
      s.specular_strength = m.specular, s.specular = m.specular_color, s.ior = m.ior;
      s.metallic_roughness_texture = texture_of(m.metallic_roughness_texture, textures);
      s.metallic_roughness_transform = m.metallic_roughness_texture.transform;
      s.metallic_roughness_uv_set = uv_set_of(m.metallic_roughness_texture);
      s.transmission = std::clamp(m.transmission, 0.f, 1.f);
      if (s.transmission > 0) {
        s.transmission_texture = texture_of(m.transmission_texture, textures);
        s.transmission_transform = m.transmission_texture.transform;
        s.transmission_uv_set = uv_set_of(m.transmission_texture);
      }
    }
    void operator()(const EmissiveMaterial&) const { s.model = SurfaceModel::kBlack; }
  };
  std::visit(Visitor{s, textures}, material.model);
  if (const auto* mr = std::get_if<MetallicRoughnessMaterial>(&material.model)) {
    s.alpha_mode = material.alpha_mode;
    s.alpha_cutoff = material.alpha_cutoff;
    s.base_alpha = mr->alpha;
    s.alpha_texture = texture_of(mr->base_color_texture, alpha_textures);
    // KHR_materials_clearcoat and _sheen (as the tracer: not over transmission).
    if (s.model == SurfaceModel::kMetallicRoughness && mr->transmission == 0 &&
        (mr->has_clearcoat() || mr->has_sheen())) {
      s.model = SurfaceModel::kLayeredMetallicRoughness;
      if (mr->has_clearcoat()) {
        s.clearcoat = mr->clearcoat;
        s.clearcoat_roughness = mr->clearcoat_roughness;
        s.clearcoat_normal_scale = mr->clearcoat_normal_scale;
        s.clearcoat_texture = slot_of(mr->clearcoat_texture, textures);
        s.clearcoat_roughness_texture = slot_of(mr->clearcoat_roughness_texture, textures);
        s.clearcoat_normal_texture = slot_of(mr->clearcoat_normal_texture, textures);
      }
      if (mr->has_sheen()) {
        s.sheen_color = mr->sheen_color;
        s.sheen_roughness = mr->sheen_roughness;
        s.sheen_color_texture = slot_of(mr->sheen_color_texture, textures);
        s.sheen_roughness_texture = slot_of(mr->sheen_roughness_texture, alpha_textures);
      }
    }
  }
  return s;
}

SurfacePoint surface_point_untextured(const SurfaceMaterial& m, Rgb vertex_color) {
  SurfacePoint p{};
  p.model = m.model;
  p.base = m.base * vertex_color;
  p.specular = m.specular;
  p.shininess = m.shininess;
  p.metallic = m.metallic;
  p.specular_strength = m.specular_strength;
  p.alpha = m.alpha;
  p.ior = m.ior;
  p.eta = m.eta, p.k = m.k, p.transmittance = m.transmittance;
  p.multiple_scattering = m.multiple_scattering;
  p.occlusion = 1;
  p.transmission = m.transmission;
  switch (m.model) {
    case SurfaceModel::kPhong:
    case SurfaceModel::kBlinnPhong:
      shading::conserve_energy(p.base, p.specular);
      p.lobe_normalization = m.model == SurfaceModel::kPhong
                                 ? shading::phong_lobe_normalization(p.shininess)
                                 : shading::blinn_phong_lobe_normalization(p.shininess);
      break;
    case SurfaceModel::kMetallicRoughness:
    case SurfaceModel::kLayeredMetallicRoughness:
      // The tracer's floor on α (twice its mirror threshold) keeps D finite in float.
      p.alpha = std::max(ggx_alpha(m.roughness), 2e-3f);
      p.specular =
          min(m.specular * (((m.ior - 1) / (m.ior + 1)) * ((m.ior - 1) / (m.ior + 1))), 1.f);
      p.clearcoat = std::clamp(m.clearcoat, 0.f, 1.f);
      p.coat_alpha = std::max(ggx_alpha(m.clearcoat_roughness), 2e-3f);
      p.sheen = m.sheen_color;
      p.sheen_alpha = shading::sheen_alpha(m.sheen_roughness);
      break;
    default:
      break;
  }
  return p;
}

SurfacePoint surface_point(const SurfaceMaterial& m, const FragmentUvs& uvs, Rgb vertex_color) {
  Rgb color = vertex_color *
              sample_or_one(m.base_texture, m.base_transform, m.filter, uvs.set[m.base_uv_set]);
  SurfacePoint p;
  if (m.model == SurfaceModel::kLayeredMetallicRoughness) {
    SurfaceMaterial textured = m;
    Rgb mr = sample_or_one(m.metallic_roughness_texture, m.metallic_roughness_transform, m.filter,
                           uvs.set[m.metallic_roughness_uv_set]);
    textured.roughness *= mr.g;
    textured.metallic *= mr.b;
    textured.clearcoat *= sample_or_one(m.clearcoat_texture, m.filter, uvs).r;
    textured.clearcoat_roughness *= sample_or_one(m.clearcoat_roughness_texture, m.filter, uvs).g;
    textured.sheen_color *= sample_or_one(m.sheen_color_texture, m.filter, uvs);
    textured.sheen_roughness *= sample_or_one(m.sheen_roughness_texture, m.filter, uvs).r;
    p = surface_point_untextured(textured, color);
  } else if (m.model == SurfaceModel::kMetallicRoughness && m.metallic_roughness_texture) {
    Rgb mr = sample_or_one(m.metallic_roughness_texture, m.metallic_roughness_transform, m.filter,
                           uvs.set[m.metallic_roughness_uv_set]);
    SurfaceMaterial textured = m;
    textured.roughness *= mr.g;
    textured.metallic *= mr.b;
    p = surface_point_untextured(textured, color);
  } else {
    p = surface_point_untextured(m, color);
  }
  if (m.occlusion_texture)
    p.occlusion = sample_or_one(m.occlusion_texture, m.occlusion_transform, m.filter,
                                uvs.set[m.occlusion_uv_set])
                      .r;
  if (m.transmission_texture)
    p.transmission *= sample_or_one(m.transmission_texture, m.transmission_transform, m.filter,
                                    uvs.set[m.transmission_uv_set])
                          .r;
  return p;
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
      // A normalized lobe reflects k_s of a uniform surround (at normal incidence, exactly).
      r.diffuse = s.base, r.specular = s.specular;
      r.roughness = std::sqrt(std::sqrt(2 / (s.shininess + 2)));
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
