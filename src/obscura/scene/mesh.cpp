#include "obscura/scene/mesh.h"

#include <algorithm>

#include "obscura/scene/deformation_step.h"

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
         color_alphas.capacity() * sizeof(float) + indices.capacity() * sizeof(uint32_t) +
         name.capacity() +
         (deformation.positions.size() * sizeof(Point3f) +
          deformation.normals.size() * sizeof(Normal3f)) *
             positions.size();
}

Mesh Mesh::posed_at(double time_s) const {
  Mesh posed = *this;
  posed.deformation = {};
  if (!deforms()) return posed;
  const MeshDeformation& d = deformation;
  const auto [i, f] = deformation_step(d, d.positions.size(), time_s);
  for (size_t v = 0; v < posed.positions.size(); ++v) {
    Point3f a = d.positions[i][v], b = d.positions[i + 1][v];
    posed.positions[v] = a + (b - a) * f;
  }
  if (d.normals.size() == d.positions.size())
    for (size_t v = 0; v < posed.normals.size(); ++v) {
      Vector3f n = to_vector(d.normals[i][v]) * (1 - f) + to_vector(d.normals[i + 1][v]) * f;
      if (length_squared(n) > 0) posed.normals[v] = Normal3f(normalize(n));
    }
  return posed;
}

}  // namespace obscura
