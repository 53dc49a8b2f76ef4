// Emissive triangles as area lights, chosen in proportion to their power (area × luminance of
// emitted radiance) and sampled uniformly by area.
#pragma once

#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"
#include "obscura/scene/scene.h"

namespace obscura {

struct AreaLightSample {
  Point3f position;
  Normal3f normal;  // the emitting side
  Rgb radiance;     // emitted towards the front side
  float pdf_area;   // density with respect to surface area over all lights (m⁻²)
};

class AreaLights {
 public:
  AreaLights() = default;
  AreaLights(const std::vector<Mesh>& meshes, const std::vector<Material>& materials);

  bool empty() const { return triangles_.empty(); }
  size_t size() const { return triangles_.size(); }
  // `u_select` picks a triangle, `u_point` a point on it.
  AreaLightSample sample(float u_select, Point2f u_point) const;
  // The area density with which sample() picks points on triangle `primitive` of mesh `mesh`
  // (0 for a triangle that is not a light): what multiple importance sampling weighs a BSDF
  // sample that hit the light against.
  float pdf_area(uint32_t mesh, uint32_t primitive) const;
  // Σ area · π · luminance(radiance): the emitted power's luminance (W), for light selection.
  double power() const { return power_; }

 private:
  struct Triangle {
    Point3f p0, p1, p2;
    Normal3f normal;
    Rgb radiance;
    float area;
  };
  std::vector<Triangle> triangles_;
  std::vector<float> cdf_;  // cumulative selection probability, cdf_.back() == 1
  // Per mesh, per triangle: its index in triangles_, or −1; empty for meshes that do not emit.
  std::vector<std::vector<int32_t>> light_of_triangle_;
  double power_ = 0;
};

}  // namespace obscura
