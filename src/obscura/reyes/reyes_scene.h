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

class ReyesScene {
 public:
  // `scene` must outlive this and not change. Throws obscura::Error for an invalid scene.
  explicit ReyesScene(const Scene& scene);

  const Scene& scene() const { return *scene_; }
  const SurfaceMotion& motion() const { return motion_; }
  const shading::SurfaceMaterial& material(uint32_t index) const { return materials_[index]; }
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
  shading::PunctualLights lights_;
  bool moves_ = false;
  Rgb environment_scale_;
  const Texture* environment_map_ = nullptr;
  Transform environment_from_world_;
};

}  // namespace obscura::reyes
