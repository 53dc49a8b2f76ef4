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
  Normal3f normal;   // the emitting side
  Rgb radiance;      // emitted towards the front side
  float pdf_area;    // density with respect to surface area over all lights (m⁻²)
};

class AreaLights {
 public:
  AreaLights() = default;
  AreaLights(const std::vector<Mesh>& meshes, const std::vector<Material>& materials);

  bool empty() const { return triangles_.empty(); }
  size_t size() const { return triangles_.size(); }
  // `u_select` picks a triangle, `u_point` a point on it.
  AreaLightSample sample(float u_select, Point2f u_point) const;

 private:
  struct Triangle {
    Point3f p0, p1, p2;
    Normal3f normal;
    Rgb radiance;
    float area;
  };
  std::vector<Triangle> triangles_;
  std::vector<float> cdf_;  // cumulative selection probability, cdf_.back() == 1
};

}  // namespace obscura
