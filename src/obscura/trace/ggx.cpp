#include "obscura/trace/ggx.h"

#include <algorithm>
#include <cmath>

#include "obscura/math/sampling.h"
#include "obscura/trace/bsdf.h"

namespace obscura {

Ggx::Ggx(float alpha) : alpha_(alpha) {}

float Ggx::alpha_from_roughness(float roughness) {
  float r = std::clamp(roughness, 0.f, 1.f);
  return r * r;
}

float Ggx::visible_D(Vector3f w, Vector3f m) const {
  float c = abs_cos_theta(w);
  if (c == 0) return 0;
  // Normals are visible from w's side of the surface (from −w's mirror when w points below).
  float w_m = w.z > 0 ? dot(w, m) : -dot(w, m);
  return w_m > 0 ? G1(w) / c * D(m) * w_m : 0.f;
}

Vector3f Ggx::sample_visible_normal(Vector3f w, Point2f u) const {
  // Stretch to the configuration where α = 1 (the hemisphere), sample the projected disk seen
  // from w with the half towards w squashed accordingly, and unstretch the normal.
  Vector3f wh = normalize(Vector3f(alpha_ * w.x, alpha_ * w.y, w.z));
  if (wh.z < 0) wh = -wh;
  Vector3f t1 = wh.z < 0.99999f ? normalize(cross(Vector3f(0, 0, 1), wh)) : Vector3f(1, 0, 0);
  Vector3f t2 = cross(wh, t1);
  Point2f p = sample_uniform_disk_polar(u);
  float h = std::sqrt(1 - p.x * p.x);
  float s = 0.5f * (1 + wh.z);
  p.y = (1 - s) * h + s * p.y;
  float pz = std::sqrt(std::max(0.f, 1 - p.x * p.x - p.y * p.y));
  Vector3f nh = t1 * p.x + t2 * p.y + wh * pz;
  return normalize(Vector3f(alpha_ * nh.x, alpha_ * nh.y, std::max(1e-6f, nh.z)));
}

}  // namespace obscura
