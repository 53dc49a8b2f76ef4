// The scene: plain authoring data that both renderers read and compile into their own forms.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/color/rgb.h"
#include "obscura/math/bounds.h"
#include "obscura/math/vector.h"

namespace obscura {

struct Material {
  std::string name;
  Rgb diffuse{0.8f, 0.8f, 0.8f};  // Lambertian albedo, linear, each in [0, 1]
  Rgb emission;                   // emitted radiance (W·sr⁻¹·m⁻²), from the front face only
};

// Indexed triangles in world space. Front faces wind counter-clockwise seen from outside:
// the geometric normal is (p1 − p0) × (p2 − p0).
struct Mesh {
  std::string name;
  std::vector<Point3f> positions;
  std::vector<uint32_t> indices;  // three per triangle
  uint32_t material = 0;          // index into Scene::materials

  size_t triangle_count() const { return indices.size() / 3; }
};

struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  Camera camera;

  size_t triangle_count() const;
  Bounds3f bounds() const;
  // Throws obscura::Error naming the first mesh, index or material reference that is invalid.
  void validate() const;
};

}  // namespace obscura
