// A scene as REYES renders it: the scene itself (its meshes are diced per frame, from the camera's
// view), where its surfaces are at any time (scene/surface_motion.h), its materials compiled once
// for the shared reflection formulas (shading/surface_material.h) and its lights
// (shading/punctual_lights.h), with the environment as the uniform surround the shading sees and
// the background behind everything.
#pragma once

#include <string>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"
#include "obscura/scene/scene.h"
#include "obscura/scene/surface_motion.h"
#include "obscura/shading/punctual_lights.h"
#include "obscura/shading/surface_material.h"

namespace obscura::reyes {

// A material's displacement as REYES applies it: `scale` metres along the normal times the
// texture's first channel (1 without one).
struct Displacement {
  double scale = 0;
  const Texture* texture = nullptr;
  TextureRef reference;
  double largest = 0;  // the most |displacement| the scale and the texture's texels can give
  double bound = 0;    // the material's displacement_bound, else `largest`
  bool any() const { return scale != 0; }
  // The displacement at texture coordinates `uv` (metres).
  double at(Point2f uv) const;
};

class ReyesScene {
 public:
  // `scene` must outlive this and not change. Throws obscura::Error for an invalid scene.
  explicit ReyesScene(const Scene& scene);

  const Scene& scene() const { return *scene_; }
  const SurfaceMotion& motion() const { return motion_; }
  const shading::SurfaceMaterial& material(uint32_t index) const { return materials_[index]; }
  const Displacement& displacement(uint32_t material) const { return displacements_[material]; }
  // Every emissive instance is a surface light too, as in the rasterizer; `ambient` is the
  // environment's mean radiance.
  const shading::PunctualLights& lights() const { return lights_; }
  // Whether anything in the scene moves or deforms over time.
  bool moves() const { return moves_; }
  // The environment's radiance towards world direction `d` (unit): the background.
  Rgb background(Vector3d d) const;

 private:
  const Scene* scene_;
  SurfaceMotion motion_;
  std::vector<shading::SurfaceMaterial> materials_;
  std::vector<Displacement> displacements_;
  shading::PunctualLights lights_;
  bool moves_ = false;
  Rgb environment_scale_;
  const Texture* environment_map_ = nullptr;
  Transform environment_from_world_;
};

}  // namespace obscura::reyes
