#include "obscura/scene/mesh.h"

namespace obscura {

Bounds3f Mesh::bounds() const {
  Bounds3f b;
  for (Point3f p : positions) b = unite(b, p);
  return b;
}

const std::vector<Point2f>& Mesh::uv_set(uint32_t set) const {
  static const std::vector<Point2f> kNone;
  return set == 0 ? uvs : set == 1 ? uvs1 : kNone;
}

size_t Mesh::memory_bytes() const {
  return positions.capacity() * sizeof(Point3f) + normals.capacity() * sizeof(Normal3f) +
         (uvs.capacity() + uvs1.capacity()) * sizeof(Point2f) +
         tangents.capacity() * sizeof(Vector4f) + colors.capacity() * sizeof(Rgb) +
         indices.capacity() * sizeof(uint32_t) + name.capacity();
}

}  // namespace obscura
