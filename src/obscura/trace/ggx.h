// The GGX (Trowbridge–Reitz) microfacet distribution, isotropic, with Smith's height-correlated
// masking-shadowing (the formulas of shading/ggx.h) and Heitz's (2018) sampling of the normals
// visible from a direction. Directions are in the local shading frame (+Z = macro-surface normal).
#pragma once

#include "obscura/math/vector.h"
#include "obscura/shading/ggx.h"

namespace obscura {

class Ggx {
 public:
  // alpha: the GGX width (glTF and most tools give roughness r and use α = r²); > 0.
  explicit Ggx(float alpha);

  float alpha() const { return alpha_; }
  // Below this width the surface is treated as perfectly smooth (a delta lobe).
  static constexpr float kSmoothAlpha = 1e-3f;
  bool effectively_smooth() const { return alpha_ < kSmoothAlpha; }
  // α = roughness², kept above a floor where float precision of D would fail.
  static float alpha_from_roughness(float roughness);

  // Microfacet normal density D(m) (sr⁻¹): ∫ D(m) cos θm dωm = 1 (shading/ggx.h).
  float D(Vector3f m) const { return shading::ggx_d(m.z, alpha_); }
  // Smith's auxiliary Λ(w); G1 = 1 / (1 + Λ).
  float lambda(Vector3f w) const { return shading::ggx_lambda(w.z * w.z, alpha_); }
  float G1(Vector3f w) const { return 1 / (1 + lambda(w)); }
  // Height-correlated masking-shadowing of the pair.
  float G(Vector3f wo, Vector3f wi) const { return shading::ggx_g(lambda(wo), lambda(wi)); }
  // The density of normals visible from w: G1(w) · max(0, w·m) · D(m) / |cos θw| (w below
  // the surface sees the normals that −w sees).
  float visible_D(Vector3f w, Vector3f m) const;
  // A microfacet normal drawn with density visible_D(w, ·); w may lie on either side (the
  // normal is then drawn for −w's mirror and lies in +Z).
  Vector3f sample_visible_normal(Vector3f w, Point2f u) const;

 private:
  float alpha_;
};

}  // namespace obscura
