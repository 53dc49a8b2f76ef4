// A material as the tracer shades it: emitted radiance and the BSDF at a hit point.
#pragma once

#include "obscura/scene/scene.h"
#include "obscura/trace/any_bsdf.h"
#include "obscura/trace/surface_hit.h"

namespace obscura {

class TraceMaterial {
 public:
  explicit TraceMaterial(AnyBsdf bsdf, Rgb emission = {}) : emission(emission), bsdf_(bsdf) {}
  // Compiles a scene material.
  static TraceMaterial from_scene(const Material& material);

  AnyBsdf bsdf_at(const SurfaceHit& /*hit*/) const { return bsdf_; }
  // Emitted radiance, from the front face only.
  Rgb emission;

 private:
  AnyBsdf bsdf_;
};

}  // namespace obscura
