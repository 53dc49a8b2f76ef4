// A metal: GGX microfacet reflection with the exact Fresnel term of a complex index η + ik
// (Walter et al. 2007; Heitz 2018 for sampling visible normals), plus Kulla–Conty's
// multiple-scattering lobe so that rough metals lose no energy between microfacets
// (shading/ggx_energy.h). Below a tiny roughness it is a perfect mirror (a delta lobe).
#pragma once

#include "obscura/trace/bsdf.h"
#include "obscura/trace/ggx.h"

namespace obscura {

struct ConductorBsdf {
  ConductorBsdf(Rgb eta, Rgb k, float alpha);

  Rgb f(Vector3f wo, Vector3f wi) const;
  float pdf(Vector3f wo, Vector3f wi) const;
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const;
  bool is_delta() const { return distribution.effectively_smooth(); }

  Rgb eta, k;
  Ggx distribution;
  Rgb multiple_scattering;         // F_ms: the colour of the multiple-scattering lobe
  float multiple_probability = 0;  // of drawing a cosine-distributed direction for it
};

}  // namespace obscura
