#include "obscura/trace/area_lights.h"

#include <algorithm>

#include "obscura/math/sampling.h"

namespace obscura {

AreaLights::AreaLights(const std::vector<Mesh>& meshes, const std::vector<Material>& materials) {
  double total_power = 0;
  std::vector<double> power;
  light_of_triangle_.resize(meshes.size());
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    Rgb radiance = materials[mesh.material].emission;
    if (radiance.is_black()) continue;
    light_of_triangle_[m].assign(mesh.triangle_count(), -1);
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      Point3f p0 = mesh.positions[mesh.indices[3 * t]];
      Point3f p1 = mesh.positions[mesh.indices[3 * t + 1]];
      Point3f p2 = mesh.positions[mesh.indices[3 * t + 2]];
      Vector3f n = cross(p1 - p0, p2 - p0);
      float area = 0.5f * length(n);
      if (area <= 0) continue;
      light_of_triangle_[m][t] = int32_t(triangles_.size());
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
  power_ = total_power * kPi;
}

float AreaLights::pdf_area(uint32_t mesh, uint32_t primitive) const {
  if (mesh >= light_of_triangle_.size() || light_of_triangle_[mesh].empty()) return 0;
  int32_t i = light_of_triangle_[mesh][primitive];
  if (i < 0) return 0;
  float p_select = cdf_[i] - (i == 0 ? 0.f : cdf_[i - 1]);
  return p_select / triangles_[i].area;
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
