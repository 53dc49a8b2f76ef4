// The Phong and Blinn-Phong reflection models (ambient + Lambert diffuse + specular lobe).
//
// Energy-conserving (the default, and the convention the tracer's PhongBsdf shares, so both
// renderers agree on direct light): the BRDF f = k_d/π + k_s·c(n)·specⁿ times the light's
// irradiance E_l (brdf.h: c(n) and the k_d + k_s ≤ 1 scaling),
//   L = k_a·I_a + Σ_lights E_l·max(0, N·L)·( k_d/π + k_s·c(n)·spec^n ).
// Classic (PhongConvention::kClassic, the textbook formula without normalization):
//   L = k_a·I_a + Σ_lights E_l·( k_d·max(0, N·L) + k_s·spec^n ).
// In both, spec = max(0, R·V) with R = 2(N·L)N − L (Phong, 1975) or max(0, N·H) with
// H = (L + V)/|L + V| (Blinn, 1977), and no light from behind the surface (N·L ≤ 0).
#pragma once

#include <cmath>

#include "obscura/color/rgb.h"
#include "obscura/raster/brdf.h"
#include "obscura/raster/lights.h"
#include "obscura/raster/varyings.h"

namespace obscura::raster {

enum class PhongConvention { kEnergyConserving, kClassic };

struct PhongMaterial {
  Rgb ambient;
  Rgb diffuse{0.8f, 0.8f, 0.8f};
  Rgb specular;
  float shininess = 32;  // the exponent n, ≥ 0
  PhongConvention convention = PhongConvention::kEnergyConserving;
};

enum class SpecularModel { kPhong, kBlinnPhong };

// max(x, 0) as a value select: std::max returns a reference, which compilers cannot always turn
// into a vector select, and that keeps a shader from vectorizing.
OBSCURA_RASTER_INLINE float positive_part(float x) {
  return x > 0.f ? x : 0.f;
}

// x^n for x in [0, 1]. Integer exponents up to 255 (the common case) use exact repeated squaring,
// which vectorizes; others fall back to std::pow.
OBSCURA_RASTER_INLINE float specular_power(float x, float n) {
  int k = int(n);
  if (float(k) == n && k >= 0 && k < 256) {
    float result = 1.f, base = x;
    for (int bit = 0; bit < 8; ++bit) {
      result *= (k >> bit) & 1 ? base : 1.f;
      base *= base;
    }
    return result;
  }
  return std::pow(x, n);
}

// The lobe's value spec^n (0 where spec ≤ 0, also for n = 0, as the tracer's BRDF).
template <SpecularModel M>
OBSCURA_RASTER_INLINE float specular_lobe(Vector3f n, Vector3f l, Vector3f v, float n_dot_l,
                                          float shininess) {
  float lobe;
  if constexpr (M == SpecularModel::kPhong) {
    Vector3f r = n * (2 * n_dot_l) - l;
    lobe = dot(r, v);
  } else {
    lobe = dot(n, normalize(l + v));
  }
  return lobe > 0.f ? specular_power(lobe, shininess) : 0.f;
}

// A Phong material ready to shade: k_d, k_s and c(n) per the convention (classic: c = 1, and
// the diffuse term's 1/π becomes 1).
struct PhongTerms {
  Rgb diffuse, specular;
  float shininess;
  float specular_cosine;  // 1: the specular term is weighted by N·L (energy-conserving); 0: not
};
template <SpecularModel M>
OBSCURA_RASTER_INLINE PhongTerms phong_terms(const PhongMaterial& m) {
  if (m.convention == PhongConvention::kClassic) return {m.diffuse, m.specular, m.shininess, 0.f};
  Rgb kd = m.diffuse, ks = m.specular;
  shading::conserve_energy(kd, ks);
  float c = M == SpecularModel::kPhong ? shading::phong_lobe_normalization(m.shininess)
                                       : shading::blinn_phong_lobe_normalization(m.shininess);
  return {kd * kBrdfInvPi, ks * c, m.shininess, 1.f};
}

template <SpecularModel M, class Light>
OBSCURA_RASTER_INLINE Rgb reflect_light(const PhongTerms& m, const Light& light, Point3f p,
                                        Vector3f n, Vector3f v) {
  IncidentLight in = incident(light, p);
  float n_dot_l = dot(n, in.to_light);
  if (n_dot_l <= 0) return {};
  float lobe = specular_lobe<M>(n, in.to_light, v, n_dot_l, m.shininess);
  float spec_weight = lobe * (m.specular_cosine * n_dot_l + (1 - m.specular_cosine));
  return in.strength * (m.diffuse * n_dot_l + m.specular * spec_weight);
}

// Reflected light at p with unit normal n, seen from unit direction v (toward the eye).
template <SpecularModel M>
OBSCURA_RASTER_INLINE Rgb shade_phong(const PhongMaterial& m, const LightSet& lights, Point3f p,
                                      Vector3f n, Vector3f v) {
  const PhongTerms terms = phong_terms<M>(m);
  Rgb sum = m.ambient * lights.ambient;
  for (const DirectionalLight& l : lights.directional) sum += reflect_light<M>(terms, l, p, n, v);
  for (const PointLight& l : lights.point) sum += reflect_light<M>(terms, l, p, n, v);
  for (const SpotLight& l : lights.spot) sum += reflect_light<M>(terms, l, p, n, v);
  for (const SurfaceLight& l : lights.surface) sum += reflect_light<M>(terms, l, p, n, v);
  return sum;
}

}  // namespace obscura::raster
