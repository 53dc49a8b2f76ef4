// Energy-conserving Phong and Blinn-Phong: the rasterizer's classic parameters (diffuse k_d,
// specular k_s, shininess n) as a physically based BRDF
//   f = k_d/π + k_s · c(n) · lobe^n,
// lobe = max(0, r·wi) with r the mirror of wo (Phong) or max(0, n·h) with h the half vector
// (Blinn-Phong). The normalizations c(n) and the k_d + k_s ≤ 1 rule are shading/phong_lobe.h's,
// the ones the rasterizer uses too.
//
// The rasterizer's classic shading of a light of intensity I at distance d is
// (I/d²)(k_d·cosθ + k_s·lobe^n); the tracer computes (I/d²)·f·cosθ, so its diffuse term is the
// classic one divided by π and its specular lobe the classic one times c(n)·cosθ.
#pragma once

#include "obscura/trace/bsdf.h"

namespace obscura {

struct PhongBsdf {
  PhongBsdf(Rgb diffuse, Rgb specular, float shininess, bool blinn);

  Rgb f(Vector3f wo, Vector3f wi) const;
  float pdf(Vector3f wo, Vector3f wi) const;
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const;

  Rgb diffuse, specular;  // after the energy-conserving scale
  float shininess;        // n ≥ 0
  bool blinn;
  float normalization;         // c(n)
  float specular_probability;  // of sampling the lobe rather than the diffuse part

 private:
  float lobe(Vector3f wo, Vector3f wi) const;
  float lobe_pdf(Vector3f wo, Vector3f wi) const;
};

}  // namespace obscura
