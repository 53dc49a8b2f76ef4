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
//   clearcoat, sheen    KHR_materials_clearcoat and _sheen: the tracer's layering
//   (glTF)              (trace/layered_metallic_roughness_bsdf.h) for every light; the
//                       environment reaches the layers through their albedos at the shading
//                       normal's n·v, the coat reflecting it at its own roughness
// Every material adds its emission (× emission texture) on its front face.
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/raster/brdf.h"
#include "obscura/raster/texture.h"
#include "obscura/raster/varyings.h"
#include "obscura/scene/material.h"
#include "obscura/shading/charlie_sheen.h"
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
  kUnlit,                    // shows its base colour, lit by nothing
  kLayeredMetallicRoughness  // kMetallicRoughness under a sheen and/or a clear coat
};

// Perfectly smooth conductors and glass reflect a punctual light in one direction only; the
// rasterizer shades them with at least this GGX width (a highlight a few pixels across).
inline constexpr float kMinHighlightAlpha = 0.02f;

// A texture, its KHR_texture_transform map and its UV set (0 or 1), for the layers' textures.
struct TextureSlot {
  const Texture* texture = nullptr;
  UvTransform transform;
  uint8_t uv_set = 0;
};

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
  // KHR_materials_clearcoat (R, G of its textures) and KHR_materials_sheen (RGB; the roughness
  // from the alpha channel, held as grey like alpha_texture), for kLayeredMetallicRoughness.
  float clearcoat = 0, clearcoat_roughness = 0, clearcoat_normal_scale = 1;
  Rgb sheen_color;
  float sheen_roughness = 0;
  TextureSlot clearcoat_texture, clearcoat_roughness_texture, clearcoat_normal_texture,
      sheen_color_texture, sheen_roughness_texture;
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
  // kLayeredMetallicRoughness: coat weight and GGX width, sheen colour and Charlie width, and
  // the coat's own unit normal facing v (zero: the shading normal), set by the program.
  float clearcoat, coat_alpha;
  Rgb sheen;
  float sheen_alpha;
  Vector3f coat_normal;
};

OBSCURA_RASTER_INLINE Rgb sample_or_one(const Texture* t, const UvTransform& m,
                                        TextureFilter filter, const TextureCoordinates& c) {
  if (!t) return Rgb(1.f);
  // The derivatives go through the map's linear part, so mip selection sees the scaled texture.
  return t->sample(filter, m.m00 * c.u + m.m01 * c.v + m.m02, m.m10 * c.u + m.m11 * c.v + m.m12,
                   m.m00 * c.du_dx + m.m01 * c.dv_dx, m.m10 * c.du_dx + m.m11 * c.dv_dx,
                   m.m00 * c.du_dy + m.m01 * c.dv_dy, m.m10 * c.du_dy + m.m11 * c.dv_dy);
}

// The coverage α at a point, for the cut-out test (see SurfaceMaterial::alpha_mode). Read from
// the full-resolution texture, bilinearly, as the tracer reads it: a cut-out is a threshold, and
// a threshold of MIP-averaged alpha moves the cut-out's edge (thin parts vanish or swell with
// distance) where the threshold of the texture itself is what the file describes. MSAA then
// antialiases the edge by testing each sample.
OBSCURA_RASTER_INLINE float coverage_alpha(const SurfaceMaterial& m, const FragmentUvs& uvs,
                                           float vertex_alpha) {
  float a = m.base_alpha * vertex_alpha;
  if (m.alpha_texture)
    a *= sample_or_one(m.alpha_texture, m.base_transform,
                       m.filter == TextureFilter::kNearest ? m.filter : TextureFilter::kBilinear,
                       uvs.set[m.base_uv_set])
             .r;
  return a;
}

SurfacePoint surface_point(const SurfaceMaterial& m, const FragmentUvs& uvs, Rgb vertex_color);
// The same without textures (Gouraud shading at vertices).
SurfacePoint surface_point_untextured(const SurfaceMaterial& m, Rgb vertex_color);

OBSCURA_RASTER_INLINE Rgb sample_or_one(const TextureSlot& slot, TextureFilter filter,
                                        const FragmentUvs& uvs) {
  return sample_or_one(slot.texture, slot.transform, filter, uvs.set[slot.uv_set]);
}

// The sheen and the clear coat over a metallic-roughness point's f·cos θ_l (`base`), term for
// term as trace/layered_metallic_roughness_bsdf.h has them.
OBSCURA_RASTER_INLINE Rgb layered_cosine(const SurfacePoint& s, Rgb base, Vector3f n, Vector3f v,
                                         Vector3f l, float n_dot_v, float n_dot_l) {
  Rgb r = base;
  float sheen_max = std::max({s.sheen.r, s.sheen.g, s.sheen.b});
  if (sheen_max > 0) {
    float e_v = shading::sheen_albedo(n_dot_v, s.sheen_alpha);
    float e_l = shading::sheen_albedo(n_dot_l, s.sheen_alpha);
    float scale = std::min(1 - sheen_max * std::min(e_v, 1.f), 1 - sheen_max * std::min(e_l, 1.f));
    float lobe = shading::charlie_sheen(n_dot_v, n_dot_l, dot(n, normalize(v + l)), s.sheen_alpha) *
                 shading::sheen_energy_bound(e_v, e_l);
    r = r * scale + s.sheen * (lobe * n_dot_l);
  }
  if (s.clearcoat > 0) {
    Vector3f nc = dot(s.coat_normal, s.coat_normal) > 0 ? s.coat_normal : n;
    float c_v = dot(nc, v), c_l = dot(nc, l);
    if (c_v > 0) {
      constexpr float kCoatF0 = 0.04f;  // IOR 1.5
      r = r * (1 - s.clearcoat * shading::ggx_schlick_albedo(kCoatF0, c_v, s.coat_alpha));
      if (c_l > 0) {
        Vector3f h = normalize(v + l);
        r += Rgb(s.clearcoat * shading::fresnel_schlick(kCoatF0, dot(v, h)) *
                 shading::ggx_specular(c_v, c_l, dot(nc, h), s.coat_alpha) * c_l);
      }
    }
  }
  return r;
}

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
    case SurfaceModel::kMetallicRoughness:
    case SurfaceModel::kLayeredMetallicRoughness: {
      // The tracer's MetallicRoughnessBsdf term for term (its header has the formula).
      Vector3f h = normalize(v + l);
      float v_h = dot(v, h);
      float lobe = shading::ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      float multiple = shading::ggx_multiple_scattering(n_dot_v, n_dot_l, s.alpha);
      float f0 = std::max({s.specular.r, s.specular.g, s.specular.b});
      float left_average =
          1 - s.specular_strength * shading::ggx_schlick_average_albedo(f0, s.alpha);
      float left_v = 1 - s.specular_strength * shading::ggx_schlick_albedo(f0, n_dot_v, s.alpha);
      float left_l = 1 - s.specular_strength * shading::ggx_schlick_albedo(f0, n_dot_l, s.alpha);
      float diffuse_weight = left_average > 1e-6f ? left_v * left_l / left_average : 0.f;
      Rgb dielectric = s.base * (diffuse_weight * kBrdfInvPi) +
                       shading::fresnel_schlick(s.specular, v_h) * (s.specular_strength * lobe);
      Rgb metal =
          shading::fresnel_schlick(s.base, v_h) * lobe +
          shading::multiple_scattering_color(shading::schlick_average(s.base), s.alpha) * multiple;
      Rgb r = (dielectric * (1 - s.metallic) + metal * s.metallic) * n_dot_l;
      return s.model == SurfaceModel::kMetallicRoughness
                 ? r
                 : layered_cosine(s, r, n, v, l, n_dot_v, n_dot_l);
    }
    case SurfaceModel::kConductor: {
      Vector3f h = normalize(v + l);
      float lobe = shading::ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      return shading::fresnel_conductor(dot(v, h), s.eta, s.k) * (lobe * n_dot_l) +
             s.multiple_scattering *
                 (shading::ggx_multiple_scattering(n_dot_v, n_dot_l, s.alpha) * n_dot_l);
    }
    case SurfaceModel::kDielectric: {
      Vector3f h = normalize(v + l);
      float lobe = shading::ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      return Rgb(shading::fresnel_dielectric_from_outside(dot(v, h), s.ior) * lobe * n_dot_l);
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
// reflectance. A clear coat adds `coat`, its own reflection of the surround at its own roughness
// (about its own normal where it has one). The occlusion texture multiplies them all.
struct EnvironmentResponse {
  Rgb diffuse, specular, transmitted;
  float roughness = 1;
  Rgb coat;  // a clear coat's reflection of the surround, at its own roughness
  float coat_roughness = 0;
};
EnvironmentResponse environment_response(const SurfacePoint& s, float n_dot_v);
// Their sum: the directional albedo, what a uniform surround of radiance 1 gives.
Rgb ambient_reflectance(const SurfacePoint& s, float n_dot_v);

}  // namespace obscura::raster
