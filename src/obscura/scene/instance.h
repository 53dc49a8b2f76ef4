// An instance places a mesh in the world; many instances may share one mesh (instancing is
// kept, not expanded). Node hierarchies are flattened: the transform is the full object→world.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "obscura/math/transform.h"

namespace obscura {

// The object→world transform at one moment of an animation.
struct TransformKey {
  double time_seconds = 0;
  Transform world_from_object;
};

struct Instance {
  std::string name;
  uint32_t mesh = 0;  // index into Scene::meshes
  // Index into Scene::materials to draw this instance with, or −1 for the mesh's own material
  // (glTF shares one geometry between meshes that differ only in material).
  int32_t material = -1;
  // KHR_materials_variants: (index into Scene::material_variants, material) pairs; selecting a
  // variant (scene/material_variants.h) draws the instance with its material for that variant.
  std::vector<std::pair<uint32_t, uint32_t>> variant_materials;
  Transform world_from_object;
  // Keyframes for motion blur, sorted by time; empty for a static instance. Between keys the
  // transform is interpolated (translation and scale linearly, rotation by slerp); before the
  // first and after the last it holds. `world_from_object` is the pose at time 0.
  std::vector<TransformKey> motion;

  bool animated() const { return motion.size() > 1; }
};

}  // namespace obscura
