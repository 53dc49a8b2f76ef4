#include "obscura/shading/punctual_lights.h"

#include <numbers>
#include <type_traits>
#include <variant>

namespace obscura::shading {

std::optional<SurfaceLight> surface_light(const Mesh& mesh, const Transform& world_from_object,
                                          Rgb radiance) {
  double area = 0;
  Vector3d centroid, normal_sum;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Point3f p[3];
    for (int k = 0; k < 3; ++k) p[k] = world_from_object(mesh.positions[mesh.indices[t + k]]);
    Vector3f n = cross(p[1] - p[0], p[2] - p[0]) * 0.5f;
    double a = length(n);
    area += a;
    normal_sum += Vector3d(n.x, n.y, n.z);
    centroid +=
        Vector3d(p[0].x + p[1].x + p[2].x, p[0].y + p[1].y + p[2].y, p[0].z + p[1].z + p[2].z) *
        (a / 3);
  }
  if (area <= 0) return std::nullopt;
  if (world_from_object.swaps_handedness()) normal_sum = -normal_sum;
  centroid = centroid / area;
  SurfaceLight light;
  light.position = Point3f(float(centroid.x), float(centroid.y), float(centroid.z));
  double flatness = length(normal_sum) / area;  // 1 for a flat emitter
  light.one_sided = flatness > 0.999;
  if (light.one_sided) {
    Vector3d n = normal_sum / length(normal_sum);
    light.normal = Vector3f(float(n.x), float(n.y), float(n.z));
    light.intensity = radiance * float(area);
    light.radius2 = float(area / std::numbers::pi);
  } else {
    light.intensity = radiance * float(area / 4);
    light.radius2 = float(area / (4 * std::numbers::pi));
  }
  return light;
}

void add_scene_lights(const Scene& scene, PunctualLights& lights) {
  for (const Light& light : scene.lights) {
    std::visit(
        [&](const auto& l) {
          using T = std::decay_t<decltype(l)>;
          if constexpr (std::is_same_v<T, obscura::PointLight>) {
            lights.point.push_back({l.position, l.intensity});
          } else if constexpr (std::is_same_v<T, obscura::SpotLight>) {
            lights.spot.push_back({l.position, normalize(l.direction), l.intensity,
                                   std::cos(l.inner_cone_radians), std::cos(l.outer_cone_radians)});
          } else {
            lights.directional.push_back({-normalize(l.direction), l.irradiance});
          }
        },
        light.model);
  }
}

}  // namespace obscura::shading
