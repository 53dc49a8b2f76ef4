// A scene material as the rasterizer shades it: one flat struct for every model, its textures
// resolved to mipmapped raster textures, evaluated per fragment (or per vertex for Gouraud).
//
// The mapping (docs/rasterizer.md has the reasoning):
//   diffuse             Lambert, reflectance × texture
//   phong               energy-conserving Phong / Blinn-Phong, the tracer's PhongBsdf
//   metallic-roughness  glTF's model as the tracer evaluates it (GGX, Smith, Schlick); metallic
//                       and roughness textures (B, G), occlusion (R) darkens the ambient term
//   conductor           GGX with the exact conductor Fresnel; a mirror's lobe is widened to
//                       α = kMinHighlightAlpha so lights show as small highlights
//   dielectric          its GGX reflection lobe with the dielectric Fresnel (widened likewise);
//                       refraction shows only as ambient light passing through
//   emissive            reflects nothing
//   unlit (glTF)        KHR_materials_unlit: base colour × texture × vertex colour, as it is
//   transmission (glTF) KHR_materials_transmission as real-time viewers draw it: a thin glass
//                       wall (no refraction) that shows what was drawn behind it, tinted by the
//                       base colour (scene_program.h, shade_transmission)
// Every material adds its emission (× emission texture) on its front face.
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/raster/brdf.h"
#include "obscura/raster/texture.h"
#include "obscura/raster/varyings.h"
#include "obscura/scene/material.h"
#include "obscura/shading/ggx_energy.h"

namespace obscura::raster {

enum class SurfaceModel : uint8_t {
  kBlack,
  kLambert,
  kPhong,
  kBlinnPhong,
  kMetallicRoughness,
  kConductor,
  kDielectric,
  kUnlit  // shows its base colour, lit by nothing
};

// Perfectly smooth conductors and glass reflect a punctual light in one direction only; the
// rasterizer shades them with at least this GGX width (a highlight a few pixels across).
inline constexpr float kMinHighlightAlpha = 0.02f;

struct SurfaceMaterial {
  SurfaceModel model = SurfaceModel::kLambert;
  Rgb base{0.8f, 0.8f, 0.8f};  // Lambert reflectance, Phong k_d, glTF base colour
  Rgb specular;                // Phong k_s; glTF KHR_materials_specular colour
  float shininess = 0;         // Phong exponent
  float metallic = 0, roughness = 1, specular_strength = 1, ior = 1.5f;  // glTF
  float alpha = 1;          // conductor, dielectric: GGX width
  Rgb eta, k;               // conductor
  Rgb multiple_scattering;  // conductor: the colour of its multiple-scattering lobe
  Rgb transmittance{1.f};   // dielectric
  Rgb emission;
  // Textures (null: none). Base multiplies `base`; metallic-roughness: G roughness, B metallic.
  const Texture* base_texture = nullptr;
  const Texture* metallic_roughness_texture = nullptr;
  const Texture* occlusion_texture = nullptr;
  const Texture* emission_texture = nullptr;
  const Texture* normal_texture = nullptr;  // tangent-space normal map (shading/normal_map.h)
  // Their KHR_texture_transform maps.
  UvTransform base_transform, metallic_roughness_transform, occlusion_transform, emission_transform,
      normal_transform;
  // Their UV sets (TextureRef::uv_set: 0 or 1, an index into FragmentUvs::set).
  uint8_t base_uv_set = 0, metallic_roughness_uv_set = 0, occlusion_uv_set = 0, emission_uv_set = 0,
          normal_uv_set = 0;
  float normal_scale = 1;  // glTF normalTexture.scale
  // KHR_materials_transmission (metallic-roughness): factor × texture (R); 0 for other models.
  float transmission = 0;
  const Texture* transmission_texture = nullptr;
  UvTransform transmission_transform;
  uint8_t transmission_uv_set = 0;
  TextureFilter filter = TextureFilter::kTrilinear;
  bool double_sided = true;
  // glTF alpha coverage, for metallic-roughness materials as in the tracer: the base colour
  // factor's alpha × the base colour texture's alpha (`alpha_texture` holds it as grey; null
  // where the texture has no alpha) × the vertex colour's alpha.
  AlphaMode alpha_mode = AlphaMode::kOpaque;
  float base_alpha = 1, alpha_cutoff = 0.5f;
  const Texture* alpha_texture = nullptr;
};

// `textures[i]` is the raster form of Scene::textures[i] (null where unused); `alpha_textures[i]`
// its alpha channel as grey (null where unused or without alpha).
SurfaceMaterial compile_material(const Material& material,
                                 const std::vector<const Texture*>& textures,
                                 const std::vector<const Texture*>& alpha_textures = {});

// Texture coordinates and their screen-space derivatives at a fragment.
struct TextureCoordinates {
  float u = 0, v = 0, du_dx = 0, dv_dx = 0, du_dy = 0, dv_dy = 0;
};
// Both texture coordinate sets a fragment has (TEXCOORD_0 and TEXCOORD_1).
struct FragmentUvs {
  TextureCoordinates set[2];
};

// The material at one point: textures applied, vertex colour multiplied into the base colour.
// Per point the fields mean what they mean in SurfaceMaterial, except: Phong's k_d/k_s are
// scaled to k_d + k_s ≤ 1; glTF's roughness is folded into `alpha`, and `specular` holds the
// dielectric F0 (KHR_materials_specular colour × ((η−1)/(η+1))², at most 1).
struct SurfacePoint {
  SurfaceModel model;
  Rgb base, specular;
  float shininess, lobe_normalization;  // Phong: n and c(n)
  float metallic, specular_strength, alpha, ior;
  Rgb eta, k, transmittance;
  Rgb multiple_scattering;  // conductor: the colour of its multiple-scattering lobe
  float occlusion;
  float transmission;  // KHR_materials_transmission, texture applied
};

OBSCURA_RASTER_INLINE Rgb sample_or_one(const Texture* t, const UvTransform& m,
                                        TextureFilter filter, const TextureCoordinates& c) {
  if (!t) return Rgb(1.f);
  // The derivatives go through the map's linear part, so mip selection sees the scaled texture.
  return t->sample(filter, m.m00 * c.u + m.m01 * c.v + m.m02, m.m10 * c.u + m.m11 * c.v + m.m12,
                   m.m00 * c.du_dx + m.m01 * c.dv_dx, m.m10 * c.du_dx + m.m11 * c.dv_dx,
                   m.m00 * c.du_dy + m.m01 * c.dv_dy, m.m10 * c.du_dy + m.m11 * c.dv_dy);
}

// The coverage α at a point (see SurfaceMaterial::alpha_mode).
OBSCURA_RASTER_INLINE float coverage_alpha(const SurfaceMaterial& m, const FragmentUvs& uvs,
                                           float vertex_alpha) {
  float a = m.base_alpha * vertex_alpha;
  if (m.alpha_texture)
    a *= sample_or_one(m.alpha_texture, m.base_transform, m.filter, uvs.set[m.base_uv_set]).r;
  return a;
}

SurfacePoint surface_point(const SurfaceMaterial& m, const FragmentUvs& uvs, Rgb vertex_color);
// The same without textures (Gouraud shading at vertices).
SurfacePoint surface_point_untextured(const SurfaceMaterial& m, Rgb vertex_color);

// f(v, l)·cos θ_l for unit n, v, l (n facing v); zero for light from behind.
OBSCURA_RASTER_INLINE Rgb reflected_cosine(const SurfacePoint& s, Vector3f n, Vector3f v,
                                           Vector3f l) {
  float n_dot_l = dot(n, l), n_dot_v = dot(n, v);
  if (n_dot_l <= 0 || n_dot_v <= 0) return {};
  switch (s.model) {
    case SurfaceModel::kBlack:
    case SurfaceModel::kUnlit:
      return {};
    case SurfaceModel::kLambert:
      return s.base * (kBrdfInvPi * n_dot_l);
    case SurfaceModel::kPhong:
    case SurfaceModel::kBlinnPhong: {
      float lobe;
      if (s.model == SurfaceModel::kPhong) {
        lobe = dot(n * (2 * n_dot_v) - v, l);  // the mirror of v against l
      } else {
        lobe = dot(n, normalize(v + l));
      }
      float spec = lobe > 0 ? std::pow(lobe, s.shininess) * s.lobe_normalization : 0.f;
      return (s.base * kBrdfInvPi + s.specular * spec) * n_dot_l;
    }
    case SurfaceModel::kMetallicRoughness: {
      // The tracer's MetallicRoughnessBsdf term for term (its header has the formula).
      Vector3f h = normalize(v + l);
      float v_h = dot(v, h);
      float lobe = ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      float multiple = shading::ggx_multiple_scattering(n_dot_v, n_dot_l, s.alpha);
      float f0 = std::max({s.specular.r, s.specular.g, s.specular.b});
      float left_average =
          1 - s.specular_strength * shading::ggx_schlick_average_albedo(f0, s.alpha);
      float left_v = 1 - s.specular_strength * shading::ggx_schlick_albedo(f0, n_dot_v, s.alpha);
      float left_l = 1 - s.specular_strength * shading::ggx_schlick_albedo(f0, n_dot_l, s.alpha);
      float diffuse_weight = left_average > 1e-6f ? left_v * left_l / left_average : 0.f;
      Rgb dielectric = s.base * (diffuse_weight * kBrdfInvPi) +
                       schlick(s.specular, v_h) * (s.specular_strength * lobe);
      Rgb metal =
          schlick(s.base, v_h) * lobe +
          shading::multiple_scattering_color(shading::schlick_average(s.base), s.alpha) * multiple;
      return (dielectric * (1 - s.metallic) + metal * s.metallic) * n_dot_l;
    }
    case SurfaceModel::kConductor: {
      Vector3f h = normalize(v + l);
      float lobe = ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      return fresnel_conductor_reflectance(dot(v, h), s.eta, s.k) * (lobe * n_dot_l) +
             s.multiple_scattering *
                 (shading::ggx_multiple_scattering(n_dot_v, n_dot_l, s.alpha) * n_dot_l);
    }
    case SurfaceModel::kDielectric: {
      Vector3f h = normalize(v + l);
      float lobe = ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      return Rgb(fresnel_dielectric_reflectance(dot(v, h), s.ior) * lobe * n_dot_l);
    }
  }
  return {};
}

// How a surface point reflects light arriving from every direction (image-based lighting,
// environment_lighting.h), split as the split-sum approximation splits it: `diffuse` weighs the
// irradiance / π, `specular` the surround prefiltered by a GGX lobe of `roughness` about the
// mirror direction, `transmitted` (glass) the same about −v. Each is a directional albedo of the
// BRDF above, integrated over a uniform surround: the GGX and Schlick terms from the
// shading/ggx_energy tables (numerical integration at startup), the diffuse weight and the
// multiple-scattering lobe as the tracer's metallic-roughness BSDF has them, so that under a
// uniform radiance L the sum × L is what the tracer converges to for a convex object. Phong's lobe
// stands in as the GGX width √(2/(n+2)); conductors use Schlick with their own normal
// reflectance. The occlusion texture multiplies all three.
struct EnvironmentResponse {
  Rgb diffuse, specular, transmitted;
  float roughness = 1;
};
EnvironmentResponse environment_response(const SurfacePoint& s, float n_dot_v);
// Their sum: the directional albedo, what a uniform surround of radiance 1 gives.
Rgb ambient_reflectance(const SurfacePoint& s, float n_dot_v);

}  // namespace obscura::raster
