#include "obscura/scene/mesh.h"

namespace obscura {

Bounds3f Mesh::bounds() const {
  Bounds3f b;
  for (Point3f p : positions) b = unite(b, p);
  return b;
}

size_t Mesh::memory_bytes() const {
  return positions.capacity() * sizeof(Point3f) + normals.capacity() * sizeof(Normal3f) +
         uvs.capacity() * sizeof(Point2f) + tangents.capacity() * sizeof(Vector4f) +
         colors.capacity() * sizeof(Rgb) + color_alphas.capacity() * sizeof(float) +
         indices.capacity() * sizeof(uint32_t) + name.capacity();
}

}  // namespace obscura
