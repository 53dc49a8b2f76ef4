#include "obscura/trace/trace_material.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "obscura/color/rgb_to_spectrum.h"
#include "obscura/math/error.h"
#include "obscura/shading/material_point.h"
#include "obscura/trace/hit_textures.h"

namespace obscura {

TraceMaterial::TraceMaterial(const Material& material, const std::vector<Texture>* textures)
    : emission(material.emission),
      emission_texture_(material.emission_texture),
      normal_texture_(material.normal_texture),
      normal_scale_(material.normal_scale),
      model_(material.model),
      textures_(textures) {
  if (material.emission_kelvin > 0) emission_spectrum_.emplace(material.emission_kelvin);
  // Coverage comes from the metallic-roughness base colour, as in glTF; other models are opaque.
  if (const auto* mr = std::get_if<MetallicRoughnessMaterial>(&material.model)) {
    alpha_mode_ = material.alpha_mode;
    alpha_cutoff_ = material.alpha_cutoff;
    alpha_ = mr->alpha;
    alpha_texture_ = mr->base_color_texture;
    unlit_ = mr->unlit;
    coat_normal_ = textures && mr->has_clearcoat() &&
                   (material.normal_texture.valid() || mr->clearcoat_normal_texture.valid());
    if (mr->has_volume() && std::isfinite(mr->attenuation_distance)) {
      attenuation_color_ = mr->attenuation_color;
      attenuation_distance_ = mr->attenuation_distance;
    }
    if (mr->has_volume() && std::isfinite(mr->attenuation_distance))
      for (int c = 0; c < 3; ++c)  // a black attenuation colour absorbs everything
        absorption_[c] =
            -std::log(std::max(mr->attenuation_color[c], 1e-30f)) / mr->attenuation_distance;
  }
}

Rgb TraceMaterial::transmittance_inside(float distance) const {
  return {std::exp(-absorption_.r * distance), std::exp(-absorption_.g * distance),
          std::exp(-absorption_.b * distance)};
}

Rgb TraceMaterial::transmittance_inside(float distance,
                                        const SampledWavelengths& wavelengths) const {
  Rgb color = lift_reflectance(attenuation_color_, wavelengths);
  Rgb t;
  for (int i = 0; i < 3; ++i)  // c^(d/D) = exp(ln(c)·d/D), a black colour absorbing everything
    t[i] = std::exp(std::log(std::max(color[i], 1e-30f)) * distance / attenuation_distance_);
  return t;
}

Rgb lift_emission(Rgb rgb, const BlackbodySpectrum* blackbody,
                  const SampledWavelengths& wavelengths) {
  if (!blackbody) return lift_illuminant(rgb, wavelengths);
  float y = luminance(rgb);
  Rgb values;
  for (int i = 0; i < SampledWavelengths::kCount; ++i)
    values[i] = y * (*blackbody)(wavelengths.nm(i));
  return values;
}

bool TraceMaterial::disperses() const {
  const auto* d = std::get_if<DielectricMaterial>(&model_);
  return !fixed_ && d && d->disperses();
}

Rgb TraceMaterial::emitted(const SurfaceHit& hit) const {
  return shading::textured(emission, emission_texture_, HitTextures(textures_, hit));
}

Rgb TraceMaterial::emitted_towards(const SurfaceHit& hit, Vector3f wo) const {
  if (unlit_) {
    const auto& mr = std::get<MetallicRoughnessMaterial>(model_);
    return shading::base_color_at(mr.base_color, mr.base_color_texture, hit.vertex_color,
                                  HitTextures(textures_, hit));
  }
  return dot(hit.geometric_normal, wo) > 0 ? emitted(hit) : Rgb();
}

bool TraceMaterial::passes_through(const SurfaceHit& hit, float u) const {
  if (alpha_mode_ == AlphaMode::kOpaque) return false;
  float alpha = alpha_ * hit.vertex_alpha;
  if (alpha_texture_.valid() && textures_)
    alpha *= HitTextures(textures_, hit).alpha(alpha_texture_);
  if (alpha_mode_ == AlphaMode::kMask) return alpha < alpha_cutoff_;
  return u >= alpha;
}

Vector3f TraceMaterial::normal_mapped(const SurfaceHit& hit, Vector3f normal,
                                      Vector4f tangent) const {
  if (!has_normal_map()) return normal;
  return shading::normal_mapped(normal_texture_, normal_scale_, normal, tangent,
                                HitTextures(textures_, hit));
}

Vector3f TraceMaterial::coat_normal_mapped(const SurfaceHit& hit, Vector3f normal,
                                           Vector4f tangent) const {
  const auto* mr = std::get_if<MetallicRoughnessMaterial>(&model_);
  if (!mr || !textures_) return normal;
  return shading::normal_mapped(mr->clearcoat_normal_texture, mr->clearcoat_normal_scale, normal,
                                tangent, HitTextures(textures_, hit));
}

AnyBsdf TraceMaterial::bsdf_at(const SurfaceHit& hit, const SampledWavelengths* wavelengths) const {
  if (fixed_) {
    if (wavelengths)
      throw Error("spectral rendering",
                  "a material given as a fixed BSDF has RGB colours that "
                  "cannot be lifted to spectra; build it from a Material");
    return *fixed_;
  }
  struct Visitor {
    const HitTextures textures;
    const SurfaceHit& hit;
    const SampledWavelengths* wavelengths;
    // A colour input at the path's wavelengths (RGB mode: as it is). Reflectances stay bounded;
    // factors above 1 (a KHR_materials_specular colour) take the unbounded lift.
    Rgb lift(Rgb rgb) const {
      if (!wavelengths) return rgb;
      return rgb.max_component() <= 1 ? lift_reflectance(rgb, *wavelengths)
                                      : lift_unbounded(rgb, *wavelengths);
    }
    // A conductor's η and k: positive numbers, not reflectances.
    Rgb lift_index(Rgb rgb) const { return wavelengths ? lift_unbounded(rgb, *wavelengths) : rgb; }
    AnyBsdf operator()(const DiffuseMaterial& m) const {
      return LambertianBsdf{lift(shading::base_color_at(m.reflectance, m.reflectance_texture,
                                                        hit.vertex_color, textures))};
    }
    AnyBsdf operator()(const PhongMaterial& m) const {
      return PhongBsdf(
          lift(shading::base_color_at(m.diffuse, m.diffuse_texture, hit.vertex_color, textures)),
          lift(m.specular), m.shininess, m.blinn);
    }
    AnyBsdf operator()(const ConductorMaterial& m) const {
      return ConductorBsdf(lift_index(m.eta), lift_index(m.k),
                           Ggx::alpha_from_roughness(m.roughness));
    }
    AnyBsdf operator()(const DielectricMaterial& m) const {
      float ior = wavelengths ? m.ior_at(wavelengths->hero_nm()) : m.ior;
      return DielectricBsdf(ior, Ggx::alpha_from_roughness(m.roughness), lift(m.transmittance));
    }
    AnyBsdf operator()(const MetallicRoughnessMaterial& m) const {
      if (m.unlit) return LambertianBsdf{Rgb(0.f)};  // its colour is emitted_towards()
      // KHR_materials_specular with a zero specular: no specular layer at all, so nothing of
      // the incoming light is held back for one (Blender exports its Diffuse BSDF this way).
      if (m.purely_diffuse())
        return LambertianBsdf{lift(shading::base_color_at(m.base_color, m.base_color_texture,
                                                          hit.vertex_color, textures))};
      const shading::MetallicRoughnessPoint at =
          shading::metallic_roughness_at(m, hit.vertex_color, textures);
      const MetallicRoughnessParameters p{.base_color = lift(at.base_color),
                                          .metallic = at.metallic,
                                          .roughness = at.roughness,
                                          .specular = at.specular,
                                          .specular_color = lift(at.specular_color),
                                          .ior = at.ior};
      if (at.transmission > 0)
        return TransmissiveMetallicRoughnessBsdf(p, at.transmission, m.has_volume());
      // KHR_materials_clearcoat and _sheen (not over transmission: docs/scene-format.md).
      const LayerParameters layers{.clearcoat = at.clearcoat,
                                   .clearcoat_roughness = at.clearcoat_roughness,
                                   .sheen_color = m.has_sheen() ? lift(at.sheen_color) : Rgb(),
                                   .sheen_roughness = at.sheen_roughness};
      if (layers.clearcoat <= 0 && layers.sheen_color.is_black()) return MetallicRoughnessBsdf(p);
      LayeredMetallicRoughnessBsdf layered(p, layers);
      if (layers.clearcoat > 0 && hit.coat_normal != Vector3f())
        layered.set_coat_normal(hit.coat_normal, to_vector(hit.shading_normal));
      return layered;
    }
    AnyBsdf operator()(const EmissiveMaterial&) const { return LambertianBsdf{Rgb(0.f)}; }
  };
  return std::visit(Visitor{HitTextures(textures_, hit), hit, wavelengths}, model_);
}

}  // namespace obscura
