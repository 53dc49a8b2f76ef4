// The Phong and Blinn-Phong reflection models (ambient + Lambert diffuse + specular lobe).
//
//   L = k_a·I_a + Σ_lights I_l·( k_d·max(0, N·L) + k_s·spec ),
//   spec = max(0, R·V)^n with R = 2(N·L)N − L   (Phong, 1975)
//   spec = max(0, N·H)^n with H = (L + V)/|L + V| (Blinn, 1977)
// and no specular from a light behind the surface (N·L ≤ 0).
#pragma once

#include <cmath>

#include "obscura/color/rgb.h"
#include "obscura/raster/lights.h"
#include "obscura/raster/varyings.h"

namespace obscura::raster {

struct PhongMaterial {
  Rgb ambient;
  Rgb diffuse{0.8f, 0.8f, 0.8f};
  Rgb specular;
  float shininess = 32;  // the exponent n, ≥ 0
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

template <SpecularModel M, class Light>
OBSCURA_RASTER_INLINE Rgb reflect_light(const PhongMaterial& m, const Light& light, Point3f p,
                                        Vector3f n, Vector3f v) {
  IncidentLight in = incident(light, p);
  float n_dot_l = dot(n, in.to_light);
  if (n_dot_l <= 0) return {};
  float lobe;
  if constexpr (M == SpecularModel::kPhong) {
    Vector3f r = n * (2 * n_dot_l) - in.to_light;
    lobe = positive_part(dot(r, v));
  } else {
    Vector3f h = normalize(in.to_light + v);
    lobe = positive_part(dot(n, h));
  }
  return in.strength * (m.diffuse * n_dot_l + m.specular * specular_power(lobe, m.shininess));
}

// Reflected light at p with unit normal n, seen from unit direction v (toward the eye).
template <SpecularModel M>
OBSCURA_RASTER_INLINE Rgb shade_phong(const PhongMaterial& m, const LightSet& lights, Point3f p,
                                      Vector3f n, Vector3f v) {
  Rgb sum = m.ambient * lights.ambient;
  for (const DirectionalLight& l : lights.directional) sum += reflect_light<M>(m, l, p, n, v);
  for (const PointLight& l : lights.point) sum += reflect_light<M>(m, l, p, n, v);
  for (const SpotLight& l : lights.spot) sum += reflect_light<M>(m, l, p, n, v);
  return sum;
}

}  // namespace obscura::raster
