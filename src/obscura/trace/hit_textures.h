// The tracer's texture lookup (shading/material_point.h's TextureLookup): a material's textures
// read at a ray hit, bilinearly from the full-resolution scene texture (scene/texture.h), at the
// hit's coordinates in the UV set the reference names. A path tracer averages many hits per
// pixel, which does the filtering a mipmap would.
#pragma once

#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/scene/texture.h"
#include "obscura/trace/surface_hit.h"

namespace obscura {

class HitTextures {
 public:
  // `textures` (Scene::textures; null: none) must outlive the lookup.
  HitTextures(const std::vector<Texture>* textures, const SurfaceHit& hit)
      : textures_(textures), hit_(hit) {}

  // RGB, or A, of the referenced texture at the hit; 1 where there is no texture.
  Rgb color(const TextureRef& texture) const;
  float alpha(const TextureRef& texture) const;

 private:
  const std::vector<Texture>* textures_;
  const SurfaceHit& hit_;
};

}  // namespace obscura
