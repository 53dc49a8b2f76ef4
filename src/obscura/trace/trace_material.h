// A material as the tracer shades it: emitted radiance and the BSDF at a hit point, with
// textured parameters looked up at the hit's texture coordinates.
#pragma once

#include <optional>
#include <vector>

#include "obscura/scene/material.h"
#include "obscura/scene/texture.h"
#include "obscura/trace/any_bsdf.h"
#include "obscura/trace/surface_hit.h"

namespace obscura {

class TraceMaterial {
 public:
  // A fixed BSDF (tests, tools).
  explicit TraceMaterial(AnyBsdf bsdf, Rgb emission = {}) : emission(emission), fixed_(bsdf) {}
  // Compiles a scene material; `textures` must outlive it.
  TraceMaterial(const Material& material, const std::vector<Texture>* textures);

  // The BSDF at `hit` (textures sampled at hit.uv).
  AnyBsdf bsdf_at(const SurfaceHit& hit) const;
  // Emitted radiance, from the front face only.
  Rgb emission;

 private:
  Rgb texture_rgb(const TextureRef& ref, const SurfaceHit& hit) const;

  std::optional<AnyBsdf> fixed_;
  MaterialModel model_;
  const std::vector<Texture>* textures_ = nullptr;
};

}  // namespace obscura
