#include "obscura/trace/area_lights.h"

#include <algorithm>
#include <cmath>

#include "obscura/math/sampling.h"
#include "obscura/math/spherical_triangle.h"

namespace obscura {

namespace {

Point3d to_double(Point3f p) {
  return {p.x, p.y, p.z};
}

}  // namespace

AreaLights::AreaLights(const std::vector<Mesh>& meshes, const std::vector<Material>& materials,
                       AreaLightSampling sampling)
    : sampling_(sampling) {
  double total_power = 0;
  std::vector<double> power;
  light_of_triangle_.resize(meshes.size());
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    Rgb radiance = materials[mesh.material].emission;
    if (radiance.is_black() || mesh.positions.empty()) continue;
    light_of_triangle_[m].assign(mesh.triangle_count(), -1);
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      Point3f p0 = mesh.positions[mesh.indices[3 * t]];
      Point3f p1 = mesh.positions[mesh.indices[3 * t + 1]];
      Point3f p2 = mesh.positions[mesh.indices[3 * t + 2]];
      Vector3f n = cross(p1 - p0, p2 - p0);
      float area = 0.5f * length(n);
      if (area <= 0) continue;
      light_of_triangle_[m][t] = int32_t(triangles_.size());
      triangles_.push_back(
          {p0, p1, p2, p0 + ((p1 - p0) + (p2 - p0)) / 3.f, Normal3f(normalize(n)), radiance, area});
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

int32_t AreaLights::index_of(uint32_t mesh, uint32_t primitive) const {
  if (mesh >= light_of_triangle_.size() || light_of_triangle_[mesh].empty()) return -1;
  return light_of_triangle_[mesh][primitive];
}

std::optional<SphericalTriangle> AreaLights::spherical(const Triangle& tri, Point3f p) const {
  if (sampling_ != AreaLightSampling::kSolidAngle) return std::nullopt;
  // Area sampling's density in solid angle is ∝ 1/J with J = cos/d² = h/d³ (h: p's distance
  // to the triangle's plane). J is smallest at the farthest vertex and at most 1/h², so
  // (d_max/h)³ bounds how much it varies over the triangle: where that is small, area sampling
  // is nearly as good and cheaper. The solid angle is judged by area · J at the centroid. Both
  // cost no inverse trigonometry, unlike the spherical triangle. (In double: d⁶ overflows float.)
  double h = std::abs(dot(tri.normal, p - tri.p0)), h3 = h * h * h;
  double d2_max = std::max(
      {length_squared(tri.p0 - p), length_squared(tri.p1 - p), length_squared(tri.p2 - p)});
  if (!(d2_max * d2_max * d2_max > kMinJacobianRatio * kMinJacobianRatio * h3 * h3))
    return std::nullopt;
  double d2_centroid = length_squared(tri.centroid - p);
  if (!(tri.area * h >= kMinSphericalSolidAngle * d2_centroid * std::sqrt(d2_centroid)))
    return std::nullopt;

  SphericalTriangle s(to_double(p), to_double(tri.p0), to_double(tri.p1), to_double(tri.p2));
  if (s.solid_angle() <= kMaxSphericalSolidAngle && s.solid_angle() > 0) return s;
  return std::nullopt;
}

float AreaLights::pdf_area(uint32_t mesh, uint32_t primitive) const {
  int32_t i = index_of(mesh, primitive);
  return i < 0 ? 0.f : selection_probability(i) / triangles_[i].area;
}

float AreaLights::pdf(Point3f p, uint32_t mesh, uint32_t primitive, Point3f light_point) const {
  int32_t i = index_of(mesh, primitive);
  if (i < 0) return 0;
  const Triangle& tri = triangles_[i];
  if (dot(tri.normal, p - tri.p0) <= 0) return 0;  // p sees the back: never sampled from there
  if (std::optional<SphericalTriangle> s = spherical(tri, p))
    return float(selection_probability(i) / s->solid_angle());
  Vector3f to_light = light_point - p;
  float d2 = length_squared(to_light);
  float cos_light = -dot(tri.normal, to_light) / std::sqrt(d2);
  if (cos_light <= 0) return 0;
  return selection_probability(i) / tri.area * d2 / cos_light;
}

AreaLightPoint AreaLights::sample_point(float u_select, Point2f u_point) const {
  size_t i = std::upper_bound(cdf_.begin(), cdf_.end(), u_select) - cdf_.begin();
  i = std::min(i, triangles_.size() - 1);
  const Triangle& tri = triangles_[i];
  Point2f b = sample_uniform_triangle(u_point);
  Point3f p = tri.p0 + (tri.p1 - tri.p0) * b.x + (tri.p2 - tri.p0) * b.y;
  return {p, tri.normal, tri.radiance, selection_probability(i) / tri.area};
}

std::optional<AreaLightSample> AreaLights::sample(Point3f p, float u_select,
                                                  Point2f u_point) const {
  size_t i = std::upper_bound(cdf_.begin(), cdf_.end(), u_select) - cdf_.begin();
  i = std::min(i, triangles_.size() - 1);
  const Triangle& tri = triangles_[i];
  if (dot(tri.normal, p - tri.p0) <= 0) return std::nullopt;  // facing away: no light here
  if (std::optional<SphericalTriangle> s = spherical(tri, p)) {
    // A direction uniform in the spherical triangle, then where it meets the triangle's plane.
    Point3d o = to_double(p);
    Vector3d w = s->sample({u_point.x, u_point.y});
    Vector3d n(tri.normal.x, tri.normal.y, tri.normal.z);
    double cos_plane = dot(n, w);
    if (cos_plane >= 0) return std::nullopt;  // numerically parallel to the plane
    double t = dot(n, to_double(tri.p0) - o) / cos_plane;
    Vector3f wi(float(w.x), float(w.y), float(w.z));
    return AreaLightSample{.wi = wi,
                           .distance = float(t),
                           .position = p + wi * float(t),
                           .normal = tri.normal,
                           .radiance = tri.radiance,
                           .pdf = float(selection_probability(i) / s->solid_angle())};
  }
  // By area: the density converts to solid angle by d²/cos at the light.
  Point2f b = sample_uniform_triangle(u_point);
  Point3f q = tri.p0 + (tri.p1 - tri.p0) * b.x + (tri.p2 - tri.p0) * b.y;
  Vector3f to_light = q - p;
  float d2 = length_squared(to_light);
  if (d2 <= 0) return std::nullopt;
  float d = std::sqrt(d2);
  Vector3f wi = to_light / d;
  float cos_light = -dot(tri.normal, wi);
  if (cos_light <= 0) return std::nullopt;
  return AreaLightSample{.wi = wi,
                         .distance = d,
                         .position = q,
                         .normal = tri.normal,
                         .radiance = tri.radiance,
                         .pdf = selection_probability(i) / tri.area * d2 / cos_light};
}

}  // namespace obscura
