#include "obscura/trace/trace_material.h"

namespace obscura {

TraceMaterial TraceMaterial::from_scene(const Material& material) {
  return TraceMaterial(LambertianBsdf{material.diffuse}, material.emission);
}

}  // namespace obscura
