// The contract every BSDF in trace/ follows, and the local shading frame it works in.
//
// A BSDF sees directions in a local frame whose +Z is the shading normal. `wo` points towards the
// viewer (where light leaves), `wi` towards where light arrives; both are unit vectors and both
// point away from the surface. Every BSDF offers
//   Rgb f(wo, wi)       the BSDF value (sr⁻¹), zero for delta (specular) lobes;
//   float pdf(wo, wi)   the solid-angle density with which sample() picks wi, zero for deltas;
//   std::optional<BsdfSample> sample(wo, uc, u)   a direction drawn with one 1D and one 2D number.
// Reflection-only BSDFs reflect on the +Z side: callers flip the frame so that wo.z > 0.
// Transmissive BSDFs (dielectrics) take the frame as given: +Z is the outside.
#pragma once

#include <cmath>
#include <optional>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"

namespace obscura {

struct BsdfSample {
  Rgb f;          // the BSDF value for (wo, wi); for a delta lobe, its weight divided by |cos θi|
  Vector3f wi;    // unit, local frame
  float pdf = 0;  // solid-angle density; for a delta lobe, the probability of choosing it
  bool is_delta = false;         // a specular direction that f()/pdf() cannot reproduce
  bool is_transmission = false;  // wi lies on the other side of the surface from wo
  float eta = 1;  // relative index of refraction across the interface (1 for reflection)
};

// Trigonometry of a local-frame unit vector.
inline float cos_theta(Vector3f w) {
  return w.z;
}
inline float abs_cos_theta(Vector3f w) {
  return std::abs(w.z);
}
inline float cos2_theta(Vector3f w) {
  return w.z * w.z;
}
inline float sin2_theta(Vector3f w) {
  return std::max(0.f, 1 - cos2_theta(w));
}
inline float tan2_theta(Vector3f w) {
  return sin2_theta(w) / cos2_theta(w);
}
inline bool same_hemisphere(Vector3f a, Vector3f b) {
  return a.z * b.z > 0;
}

// Mirror reflection of w about the unit vector n (both pointing away from the surface).
inline Vector3f reflect(Vector3f w, Vector3f n) {
  return -w + n * (2 * dot(w, n));
}

// Refraction of wi (pointing away from the surface) through the interface with unit normal n
// and relative index eta = η_inside / η_outside, where n points outside. Returns false under
// total internal reflection. On success `*eta_relative` is the index ratio actually crossed.
bool refract(Vector3f wi, Vector3f n, float eta, Vector3f* wt, float* eta_relative);

// An orthonormal frame: world ↔ local, with the local +Z along `n`.
struct ShadingFrame {
  Vector3f s, t, n;

  static ShadingFrame from_normal(Vector3f n) {
    ShadingFrame frame;
    frame.n = n;
    coordinate_system(n, &frame.s, &frame.t);
    return frame;
  }
  Vector3f to_local(Vector3f v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  Vector3f to_world(Vector3f v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace obscura
