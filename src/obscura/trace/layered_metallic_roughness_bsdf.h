// The glTF metallic-roughness BSDF under KHR_materials_sheen and KHR_materials_clearcoat, in
// the order the extensions stack them: the base, a sheen over it, a clear coat over both.
//
//   sheened = sheen_color · b · f_sheen + base · min(1 − m·E_s(μo), 1 − m·E_s(μi))
//   f       = c · F_c(wo_c·h_c) · f_coat(wo_c, wi_c) · μi_c/μi + (1 − c·E_c(μo_c)) · sheened
//
// Sheen (the specification's albedo scaling): f_sheen is the Charlie lobe
// (shading/charlie_sheen.h), m the largest component of the sheen colour, E_s the lobe's
// directional albedo (clamped to 1) and b = min(1, 1/E_s(μo), 1/E_s(μi)) the bound that keeps
// the fitted lobe from reflecting more than arrives at grazing angles. The base gets what the
// sheen leaves on both the way in and the way out.
//
// Clear coat: a GGX lobe of width α_c = roughness_c² with Schlick's Fresnel F_c (F0 = 0.04,
// IOR 1.5), weighted by c, evaluated in the coat's own frame (its normal n_c: wo_c, wi_c, μ_c
// are measured against it; μi_c/μi turns its cosine into the base frame's, which integrators
// multiply by). One departure from the specification, which weighs coat and base by
// c·F(n_c·v) (the Fresnel of the macro-normal): the base here keeps 1 − c·E_c(μo_c), where
// E_c is the coat lobe's own Fresnel-weighted albedo (shading/ggx_energy.h) and the coat uses
// the per-microfacet F(v·h) like glTF's other specular lobes. For a smooth coat the two agree
// (E_c(μ) = F(μ)); for a rough one the specification loses the energy the coat's single
// scattering drops and reflects less than arrives, while this keeps a white base under any
// coat at exactly what arrives: c·E_c + (1 − c·E_c)·1 = 1. Like the specification's weight, it
// depends on the view only, so the coat layer is not reciprocal (a unidirectional path tracer
// does not need it to be).
//
// Sampling picks coat, sheen (uniform over the hemisphere) or base in proportion to their
// approximate albedo seen from wo, then evaluates the mixture pdf. With no coat and no sheen the
// BSDF is the plain MetallicRoughnessBsdf bit for bit (tests check it), though TraceMaterial
// returns the plain one then.
#pragma once

#include "obscura/trace/bsdf.h"
#include "obscura/trace/ggx.h"
#include "obscura/trace/metallic_roughness_bsdf.h"

namespace obscura {

struct LayerParameters {
  float clearcoat = 0;  // c, in [0, 1]
  float clearcoat_roughness = 0;
  Rgb sheen_color{0.f};  // black: no sheen
  float sheen_roughness = 0;
};

class LayeredMetallicRoughnessBsdf {
 public:
  LayeredMetallicRoughnessBsdf(const MetallicRoughnessParameters& base,
                               const LayerParameters& layers);

  // The coat's own normal (world, unit), given with the shading normal it departs from; the
  // coat uses it once orient() has the frame the BSDF is evaluated in. Without one the coat
  // lies on the shading frame's +Z.
  void set_coat_normal(Vector3f coat_world, Vector3f shading_world);
  // Called by integrators with the local frame (its normal may be the shading normal turned to
  // the viewer): expresses the coat normal in it, kept above the surface.
  void orient(const ShadingFrame& frame);

  Rgb f(Vector3f wo, Vector3f wi) const;
  float pdf(Vector3f wo, Vector3f wi) const;
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const;

  MetallicRoughnessBsdf base;
  LayerParameters layers;

 private:
  struct Choice {
    float coat = 0, sheen = 0;  // probabilities of sampling those lobes; the base has the rest
  };
  Choice choice(Vector3f wo) const;
  Vector3f to_coat(Vector3f w) const { return coat_tilted_ ? coat_frame_.to_local(w) : w; }
  float coat_pdf(Vector3f wo_c, Vector3f wi_c) const;

  Ggx coat_;
  float sheen_alpha_;
  float sheen_max_;    // m: the sheen colour's largest component
  float base_albedo_;  // a rough estimate of the base's albedo, for choosing lobes
  Vector3f coat_world_, shading_world_;
  bool has_coat_normal_ = false, coat_tilted_ = false;
  ShadingFrame coat_frame_;  // coat-local ↔ the BSDF's local frame
};

}  // namespace obscura
