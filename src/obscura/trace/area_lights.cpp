#include "obscura/trace/area_lights.h"

#include <algorithm>

#include "obscura/math/sampling.h"

namespace obscura {

AreaLights::AreaLights(const std::vector<Mesh>& meshes, const std::vector<Material>& materials) {
  double total_power = 0;
  std::vector<double> power;
  for (const Mesh& mesh : meshes) {
    Rgb radiance = materials[mesh.material].emission;
    if (radiance.is_black()) continue;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      Point3f p0 = mesh.positions[mesh.indices[3 * t]];
      Point3f p1 = mesh.positions[mesh.indices[3 * t + 1]];
      Point3f p2 = mesh.positions[mesh.indices[3 * t + 2]];
      Vector3f n = cross(p1 - p0, p2 - p0);
      float area = 0.5f * length(n);
      if (area <= 0) continue;
      triangles_.push_back({p0, p1, p2, Normal3f(normalize(n)), radiance, area});
      power.push_back(double(area) * luminance(radiance));
      total_power += power.back();
    }
  }
  double running = 0;
  for (double p : power) {
    running += p;
    cdf_.push_back(float(running / total_power));
  }
  if (!cdf_.empty()) cdf_.back() = 1;
}

AreaLightSample AreaLights::sample(float u_select, Point2f u_point) const {
  size_t i = std::upper_bound(cdf_.begin(), cdf_.end(), u_select) - cdf_.begin();
  i = std::min(i, triangles_.size() - 1);
  float p_select = cdf_[i] - (i == 0 ? 0.f : cdf_[i - 1]);
  const Triangle& tri = triangles_[i];
  Point2f b = sample_uniform_triangle(u_point);
  Point3f p = tri.p0 + (tri.p1 - tri.p0) * b.x + (tri.p2 - tri.p0) * b.y;
  return {p, tri.normal, tri.radiance, p_select / tri.area};
}

}  // namespace obscura
