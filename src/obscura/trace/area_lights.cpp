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

// The share of a triangle's emission factor its texture lets through, for choosing lights: the
// mean luminance at seven points (vertices, edge midpoints, centroid), but never below 1 % so that
// a triangle whose bright texels fall between those points can still be chosen (no bias; only
// the variance depends on this estimate).
double texture_weight(const Texture& texture, const UvTransform& transform, Point2f uv0,
                      Point2f uv1, Point2f uv2) {
  const Point2f b[7] = {
      {0, 0}, {1, 0}, {0, 1}, {0.5f, 0}, {0, 0.5f}, {0.5f, 0.5f}, {1 / 3.f, 1 / 3.f}};
  double sum = 0;
  for (Point2f w : b) {
    Point2f uv{uv0.x + (uv1.x - uv0.x) * w.x + (uv2.x - uv0.x) * w.y,
               uv0.y + (uv1.y - uv0.y) * w.x + (uv2.y - uv0.y) * w.y};
    Vector4f v = sample_texture(texture, transform(uv));
    sum += luminance(Rgb(v.x, v.y, v.z));
  }
  return std::max(sum / 7, 0.01);
}

}  // namespace

AreaLights::AreaLights(const std::vector<Mesh>& meshes, const std::vector<Material>& materials,
                       AreaLightSampling sampling, const std::vector<Texture>* textures)
    : sampling_(sampling) {
  double total_power = 0;
  std::vector<double> power;
  light_of_triangle_.resize(meshes.size());
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    const Material& material = materials[mesh.material];
    Rgb radiance = material.emission;
    if (radiance.is_black() || mesh.positions.empty()) continue;
    const Texture* texture = nullptr;
    const std::vector<Point2f>& uvs = mesh.uv_set(material.emission_texture.uv_set);
    if (material.emission_texture.valid() && textures && !uvs.empty() &&
        size_t(material.emission_texture.texture) < textures->size())
      texture = &(*textures)[material.emission_texture.texture];
    light_of_triangle_[m].assign(mesh.triangle_count(), -1);
    int32_t spectrum = -1;
    if (material.emission_kelvin > 0) {
      spectrum = int32_t(spectra_.size());
      spectra_.emplace_back(material.emission_kelvin);
    }
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      Point3f p0 = mesh.positions[mesh.indices[3 * t]];
      Point3f p1 = mesh.positions[mesh.indices[3 * t + 1]];
      Point3f p2 = mesh.positions[mesh.indices[3 * t + 2]];
      Vector3f n = cross(p1 - p0, p2 - p0);
      float area = 0.5f * length(n);
      if (area <= 0) continue;
      light_of_triangle_[m][t] = int32_t(triangles_.size());
      Triangle tri;
      tri.p0 = p0, tri.p1 = p1, tri.p2 = p2;
      tri.centroid = p0 + ((p1 - p0) + (p2 - p0)) / 3.f;
      tri.normal = Normal3f(normalize(n));
      tri.radiance = radiance;
      tri.area = area;
      tri.spectrum = spectrum;
      double weight = 1;
      if (texture) {
        tri.texture = texture;
        tri.uv0 = uvs[mesh.indices[3 * t]];
        tri.uv1 = uvs[mesh.indices[3 * t + 1]];
        tri.uv2 = uvs[mesh.indices[3 * t + 2]];
        tri.transform = material.emission_texture.transform;
        weight = texture_weight(*texture, tri.transform, tri.uv0, tri.uv1, tri.uv2);
      }
      triangles_.push_back(tri);
      power.push_back(double(area) * luminance(radiance) * weight);
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

Rgb AreaLights::radiance_at(const Triangle& tri, Point2f b) {
  if (!tri.texture) return tri.radiance;
  Point2f uv{tri.uv0.x + (tri.uv1.x - tri.uv0.x) * b.x + (tri.uv2.x - tri.uv0.x) * b.y,
             tri.uv0.y + (tri.uv1.y - tri.uv0.y) * b.x + (tri.uv2.y - tri.uv0.y) * b.y};
  Vector4f v = sample_texture(*tri.texture, tri.transform(uv));
  return tri.radiance * Rgb(v.x, v.y, v.z);
}

Point2f AreaLights::barycentric(const Triangle& tri, Point3f q) {
  Vector3f e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0, v = q - tri.p0;
  float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  float v1 = dot(v, e1), v2 = dot(v, e2);
  float det = d11 * d22 - d12 * d12;
  if (!(det > 0)) return {1 / 3.f, 1 / 3.f};
  return {(d22 * v1 - d12 * v2) / det, (d11 * v2 - d12 * v1) / det};
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
  return {p, tri.normal, radiance_at(tri, b), selection_probability(i) / tri.area,
          spectrum_of(tri)};
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
    Point3f q = p + wi * float(t);
    return AreaLightSample{
        .wi = wi,
        .distance = float(t),
        .position = q,
        .normal = tri.normal,
        .radiance = tri.texture ? radiance_at(tri, barycentric(tri, q)) : tri.radiance,
        .pdf = float(selection_probability(i) / s->solid_angle()),
        .spectrum = spectrum_of(tri)};
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
                         .radiance = radiance_at(tri, b),
                         .pdf = selection_probability(i) / tri.area * d2 / cos_light,
                         .spectrum = spectrum_of(tri)};
}

}  // namespace obscura
