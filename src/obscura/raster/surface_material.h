// A scene material as the rasterizer shades it: one flat struct for every model, evaluated per
// fragment (or per vertex for Gouraud). Its textures are read through the mipmapped raster
// textures (fragment_textures.h), and which texture multiplies which factor is decided where the
// tracer's is, in shading/material_point.h.
//
// The mapping (docs/rasterizer.md has the reasoning):
//   diffuse             Lambert, reflectance × texture
//   phong               energy-conserving Phong / Blinn-Phong, the tracer's PhongBsdf
//   metallic-roughness  glTF's model as the tracer evaluates it (GGX, Smith, Schlick), with
//                       KHR_materials_specular and _ior; occlusion (R) darkens the ambient term
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

#include "obscura/color/rgb.h"
#include "obscura/raster/brdf.h"
#include "obscura/raster/fragment_textures.h"
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

struct SurfaceMaterial {
  SurfaceModel model = SurfaceModel::kLambert;
  Rgb base{0.8f, 0.8f, 0.8f};  // Lambert reflectance, Phong k_d, an unlit glTF base colour
  Rgb specular;                // Phong k_s
  float shininess = 0;         // Phong exponent
  float alpha = 1;             // conductor, dielectric: GGX width
  float ior = 1.5f;            // dielectric
  Rgb eta, k;                  // conductor
  Rgb multiple_scattering;     // conductor: the colour of its multiple-scattering lobe
  Rgb transmittance{1.f};      // dielectric
  // kMetallicRoughness, kLayeredMetallicRoughness: the scene's factors and textures, read at
  // each point as the tracer reads them (shading/material_point.h). Its clear coat and sheen
  // are dropped where the model is not layered (under transmission, as in the tracer).
  MetallicRoughnessMaterial metallic_roughness;
  Rgb emission;
  // The textures below are references into `textures` (null: none at all). `base_texture`
  // multiplies `base` (the glTF base colour texture for metallic-roughness: Gouraud shading
  // modulates with it); occlusion (R) darkens the ambient term; the normal map is tangent-space
  // (shading/normal_map.h) with glTF's normalTexture.scale.
  const TextureTable* textures = nullptr;
  TextureRef base_texture, occlusion_texture, emission_texture, normal_texture;
  float normal_scale = 1;
  TextureFilter filter = TextureFilter::kTrilinear;
  bool double_sided = true;
  // glTF alpha coverage, for metallic-roughness materials as in the tracer: the base colour
  // factor's alpha × the A of `alpha_texture` (the base colour texture, read through the table's
  // alpha column) × the vertex colour's alpha.
  AlphaMode alpha_mode = AlphaMode::kOpaque;
  float base_alpha = 1, alpha_cutoff = 0.5f;
  TextureRef alpha_texture;

  // KHR_materials_transmission: drawn after the opaque surfaces, over what they left behind.
  bool transmits() const {
    return model == SurfaceModel::kMetallicRoughness && metallic_roughness.transmission > 0;
  }
};

// `textures` is the raster form of the scene's textures (null: draw without textures); it must
// outlive the material.
SurfaceMaterial compile_material(const Material& material, const TextureTable* textures);

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

// The coverage α at a point, for the cut-out test (see SurfaceMaterial::alpha_mode). Read from
// the full-resolution texture, bilinearly, as the tracer reads it: a cut-out is a threshold, and
// a threshold of MIP-averaged alpha moves the cut-out's edge (thin parts vanish or swell with
// distance) where the threshold of the texture itself is what the file describes. MSAA then
// antialiases the edge by testing each sample.
OBSCURA_RASTER_INLINE float coverage_alpha(const SurfaceMaterial& m, const FragmentUvs& uvs,
                                           float vertex_alpha) {
  const TextureFilter full_resolution =
      m.filter == TextureFilter::kNearest ? m.filter : TextureFilter::kBilinear;
  return m.base_alpha * vertex_alpha *
         FragmentTextures(m.textures, full_resolution, uvs).alpha(m.alpha_texture);
}

SurfacePoint surface_point(const SurfaceMaterial& m, const FragmentUvs& uvs, Rgb vertex_color);
// The same without textures (Gouraud shading at vertices).
SurfacePoint surface_point_untextured(const SurfaceMaterial& m, Rgb vertex_color);

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
