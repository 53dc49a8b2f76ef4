// Fresnel reflectance: how much light an interface reflects (the rest is transmitted or, in a
// conductor, absorbed). Unpolarized light; cosines are measured against the interface normal.
// Shared by the tracer's BSDFs and the rasterizer's per-pixel BRDFs.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>

#include "obscura/color/rgb.h"
#include "obscura/shading/inline.h"

namespace obscura::shading {

// Dielectric interface with relative index eta = η_inside / η_outside. A negative cos_theta_i
// means light arrives from inside. Returns 1 under total internal reflection.
OBSCURA_SHADING_INLINE float fresnel_dielectric(float cos_theta_i, float eta) {
  cos_theta_i = std::clamp(cos_theta_i, -1.f, 1.f);
  if (cos_theta_i < 0) {  // arriving from inside: swap the media
    eta = 1 / eta;
    cos_theta_i = -cos_theta_i;
  }
  float sin2_theta_t = (1 - cos_theta_i * cos_theta_i) / (eta * eta);
  if (sin2_theta_t >= 1) return 1;
  float cos_theta_t = std::sqrt(std::max(0.f, 1 - sin2_theta_t));
  float r_parallel = (eta * cos_theta_i - cos_theta_t) / (eta * cos_theta_i + cos_theta_t);
  float r_perpendicular = (cos_theta_i - eta * cos_theta_t) / (cos_theta_i + eta * cos_theta_t);
  return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

// The same for light that can only arrive from outside (a rasterized surface seen from its
// front): a direction below the surface counts as grazing and reflects everything.
OBSCURA_SHADING_INLINE float fresnel_dielectric_from_outside(float cos_theta_i, float eta) {
  return fresnel_dielectric(std::clamp(cos_theta_i, 0.f, 1.f), eta);
}

// Conductor with complex index η + ik, light arriving from a medium of index 1 (either side:
// only |cos θi| matters).
inline float fresnel_conductor(float cos_theta_i, float eta, float k) {
  // The dielectric formulas hold with a complex index; cos θt becomes complex too.
  using Complex = std::complex<float>;
  cos_theta_i = std::clamp(std::abs(cos_theta_i), 0.f, 1.f);
  Complex n(eta, k);
  float sin2_theta_i = 1 - cos_theta_i * cos_theta_i;
  Complex sin2_theta_t = sin2_theta_i / (n * n);
  Complex cos_theta_t = std::sqrt(Complex(1) - sin2_theta_t);
  Complex r_parallel = (n * cos_theta_i - cos_theta_t) / (n * cos_theta_i + cos_theta_t);
  Complex r_perpendicular = (cos_theta_i - n * cos_theta_t) / (cos_theta_i + n * cos_theta_t);
  return 0.5f * (std::norm(r_parallel) + std::norm(r_perpendicular));
}
inline Rgb fresnel_conductor(float cos_theta_i, Rgb eta, Rgb k) {
  return {fresnel_conductor(cos_theta_i, eta.r, k.r), fresnel_conductor(cos_theta_i, eta.g, k.g),
          fresnel_conductor(cos_theta_i, eta.b, k.b)};
}

// Schlick's approximation F0 + (1 − F0)(1 − |cos θ|)⁵, the form glTF's material model uses.
OBSCURA_SHADING_INLINE float fresnel_schlick(float f0, float cos_theta) {
  float m = std::clamp(1 - std::abs(cos_theta), 0.f, 1.f);
  float m2 = m * m;
  return f0 + (1 - f0) * (m2 * m2 * m);
}
OBSCURA_SHADING_INLINE Rgb fresnel_schlick(Rgb f0, float cos_theta) {
  return {fresnel_schlick(f0.r, cos_theta), fresnel_schlick(f0.g, cos_theta),
          fresnel_schlick(f0.b, cos_theta)};
}

// Reflectance at normal incidence of a dielectric of relative index eta: ((η − 1)/(η + 1))².
inline float fresnel_f0(float eta) {
  float r = (eta - 1) / (eta + 1);
  return r * r;
}

}  // namespace obscura::shading
