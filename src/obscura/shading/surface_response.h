// A surface point's reflection of light as both the rasterizer and REYES shade it: the material
// at the point in the form the reflection formulas take (SurfacePoint), the light it reflects
// from one direction (reflected_cosine: Lambert, energy-conserving Phong/Blinn-Phong, GGX
// metallic-roughness with its layers, conductors, dielectrics) and from a uniform surround
// (environment_response). Moved down from raster/ so that every renderer that shades with the
// rasterizer's formulas evaluates these very lines; the formulas themselves (GGX, Fresnel, the
// Phong lobes) are the tracer's, in the headers included here.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"
#include "obscura/shading/charlie_sheen.h"
#include "obscura/shading/fresnel.h"
#include "obscura/shading/ggx.h"
#include "obscura/shading/ggx_energy.h"
#include "obscura/shading/inline.h"
#include "obscura/shading/phong_lobe.h"

namespace obscura::shading {

inline constexpr float kSurfaceInvPi = std::numbers::inv_pi_v<float>;

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

// The sheen and the clear coat over a metallic-roughness point's f·cos θ_l (`base`), term for
// term as trace/layered_metallic_roughness_bsdf.h has them.
OBSCURA_SHADING_INLINE Rgb layered_cosine(const SurfacePoint& s, Rgb base, Vector3f n, Vector3f v,
                                          Vector3f l, float n_dot_v, float n_dot_l) {
  Rgb r = base;
  float sheen_max = std::max({s.sheen.r, s.sheen.g, s.sheen.b});
  if (sheen_max > 0) {
    float e_v = sheen_albedo(n_dot_v, s.sheen_alpha);
    float e_l = sheen_albedo(n_dot_l, s.sheen_alpha);
    float scale = std::min(1 - sheen_max * std::min(e_v, 1.f), 1 - sheen_max * std::min(e_l, 1.f));
    float lobe = charlie_sheen(n_dot_v, n_dot_l, dot(n, normalize(v + l)), s.sheen_alpha) *
                 sheen_energy_bound(e_v, e_l);
    r = r * scale + s.sheen * (lobe * n_dot_l);
  }
  if (s.clearcoat > 0) {
    Vector3f nc = dot(s.coat_normal, s.coat_normal) > 0 ? s.coat_normal : n;
    float c_v = dot(nc, v), c_l = dot(nc, l);
    if (c_v > 0) {
      constexpr float kCoatF0 = 0.04f;  // IOR 1.5
      r = r * (1 - s.clearcoat * ggx_schlick_albedo(kCoatF0, c_v, s.coat_alpha));
      if (c_l > 0) {
        Vector3f h = normalize(v + l);
        r += Rgb(s.clearcoat * fresnel_schlick(kCoatF0, dot(v, h)) *
                 ggx_specular(c_v, c_l, dot(nc, h), s.coat_alpha) * c_l);
      }
    }
  }
  return r;
}

// f(v, l)·cos θ_l for unit n, v, l (n facing v); zero for light from behind.
OBSCURA_SHADING_INLINE Rgb reflected_cosine(const SurfacePoint& s, Vector3f n, Vector3f v,
                                            Vector3f l) {
  float n_dot_l = dot(n, l), n_dot_v = dot(n, v);
  if (n_dot_l <= 0 || n_dot_v <= 0) return {};
  switch (s.model) {
    case SurfaceModel::kBlack:
    case SurfaceModel::kUnlit:
      return {};
    case SurfaceModel::kLambert:
      return s.base * (kSurfaceInvPi * n_dot_l);
    case SurfaceModel::kPhong:
    case SurfaceModel::kBlinnPhong: {
      float lobe;
      if (s.model == SurfaceModel::kPhong) {
        lobe = dot(n * (2 * n_dot_v) - v, l);  // the mirror of v against l
      } else {
        lobe = dot(n, normalize(v + l));
      }
      float spec = lobe > 0 ? std::pow(lobe, s.shininess) * s.lobe_normalization : 0.f;
      return (s.base * kSurfaceInvPi + s.specular * spec) * n_dot_l;
    }
    case SurfaceModel::kMetallicRoughness:
    case SurfaceModel::kLayeredMetallicRoughness: {
      // The tracer's MetallicRoughnessBsdf term for term (its header has the formula).
      Vector3f h = normalize(v + l);
      float v_h = dot(v, h);
      float lobe = ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      float multiple = ggx_multiple_scattering(n_dot_v, n_dot_l, s.alpha);
      float f0 = std::max({s.specular.r, s.specular.g, s.specular.b});
      float left_average = 1 - s.specular_strength * ggx_schlick_average_albedo(f0, s.alpha);
      float left_v = 1 - s.specular_strength * ggx_schlick_albedo(f0, n_dot_v, s.alpha);
      float left_l = 1 - s.specular_strength * ggx_schlick_albedo(f0, n_dot_l, s.alpha);
      float diffuse_weight = left_average > 1e-6f ? left_v * left_l / left_average : 0.f;
      Rgb dielectric = s.base * (diffuse_weight * kSurfaceInvPi) +
                       fresnel_schlick(s.specular, v_h) * (s.specular_strength * lobe);
      Rgb metal = fresnel_schlick(s.base, v_h) * lobe +
                  multiple_scattering_color(schlick_average(s.base), s.alpha) * multiple;
      Rgb r = (dielectric * (1 - s.metallic) + metal * s.metallic) * n_dot_l;
      return s.model == SurfaceModel::kMetallicRoughness
                 ? r
                 : layered_cosine(s, r, n, v, l, n_dot_v, n_dot_l);
    }
    case SurfaceModel::kConductor: {
      Vector3f h = normalize(v + l);
      float lobe = ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      return fresnel_conductor(dot(v, h), s.eta, s.k) * (lobe * n_dot_l) +
             s.multiple_scattering * (ggx_multiple_scattering(n_dot_v, n_dot_l, s.alpha) * n_dot_l);
    }
    case SurfaceModel::kDielectric: {
      Vector3f h = normalize(v + l);
      float lobe = ggx_specular(n_dot_v, n_dot_l, dot(n, h), s.alpha);
      return Rgb(fresnel_dielectric_from_outside(dot(v, h), s.ior) * lobe * n_dot_l);
    }
  }
  return {};
}

// How a surface point reflects light arriving from every direction (image-based lighting,
// raster/environment_lighting.h), split as the split-sum approximation splits it: `diffuse` weighs
// the irradiance / π, `specular` the surround prefiltered by a GGX lobe of `roughness` about the
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

}  // namespace obscura::shading
