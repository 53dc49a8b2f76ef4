#include "obscura/scene/scene.h"

#include <cmath>

#include "obscura/math/error.h"

namespace obscura {

size_t Scene::triangle_count() const {
  size_t n = 0;
  for (const Mesh& m : meshes) n += m.triangle_count();
  return n;
}

Bounds3f Scene::bounds() const {
  Bounds3f b;
  for (const Mesh& m : meshes)
    for (Point3f p : m.positions) b = unite(b, p);
  return b;
}

void Scene::validate() const {
  for (const Mesh& m : meshes) {
    std::string where = "scene '" + name + "', mesh '" + m.name + "'";
    if (m.indices.size() % 3 != 0)
      throw Error(where, "index count " + std::to_string(m.indices.size()) +
                             " is not a multiple of 3");
    for (size_t i = 0; i < m.indices.size(); ++i)
      if (m.indices[i] >= m.positions.size())
        throw Error(where, "index " + std::to_string(i) + " = " + std::to_string(m.indices[i]) +
                               " is past the vertex count " + std::to_string(m.positions.size()));
    for (size_t i = 0; i < m.positions.size(); ++i) {
      Point3f p = m.positions[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw Error(where, "vertex " + std::to_string(i) + " is not finite");
    }
    if (m.material >= materials.size())
      throw Error(where, "material index " + std::to_string(m.material) +
                             " is past the material count " + std::to_string(materials.size()));
  }
  camera.validate();
}

}  // namespace obscura
