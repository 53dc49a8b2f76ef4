// Small scenes for the integrator tests, built in code.
#pragma once

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>

#include "obscura/camera/frames.h"
#include "obscura/math/error.h"
#include "obscura/scene/scene.h"
#include "obscura/trace/embree_scene.h"

namespace obscura::testing {

// One Embree device for every test in the process (creating one costs milliseconds).
inline std::shared_ptr<EmbreeDevice> embree_device() {
  static auto device = std::make_shared<EmbreeDevice>();
  return device;
}

// A UV sphere of `radius` at `centre`, wound counter-clockwise seen from outside.
inline Mesh make_sphere(Point3f centre, float radius, uint32_t material, int rings = 48,
                        int segments = 96) {
  Mesh mesh;
  mesh.name = "sphere";
  mesh.material = material;
  const float pi = std::numbers::pi_v<float>;
  for (int r = 0; r <= rings; ++r) {
    float theta = pi * r / rings;
    for (int s = 0; s <= segments; ++s) {
      float phi = 2 * pi * s / segments;
      mesh.positions.push_back({centre.x + radius * std::sin(theta) * std::cos(phi),
                                centre.y + radius * std::cos(theta),
                                centre.z - radius * std::sin(theta) * std::sin(phi)});
    }
  }
  auto at = [&](int r, int s) { return uint32_t(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      uint32_t a = at(r, s), b = at(r + 1, s), c = at(r + 1, s + 1), d = at(r, s + 1);
      if (r != 0) mesh.indices.insert(mesh.indices.end(), {a, b, d});
      if (r != rings - 1) mesh.indices.insert(mesh.indices.end(), {b, c, d});
    }
  return mesh;
}

// A pinhole camera at `eye` looking at `target`, square film of `size` pixels and the given
// horizontal field of view.
// A quad p0 p1 p2 p3 as two triangles; its front face is the side (p1 − p0) × (p2 − p0) points to.
inline Mesh make_quad(const char* name, uint32_t material, Point3f p0, Point3f p1, Point3f p2,
                      Point3f p3) {
  Mesh mesh;
  mesh.name = name;
  mesh.positions = {p0, p1, p2, p3};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  return mesh;
}

inline Camera make_camera(Point3d eye, Point3d target, int size, double hfov_degrees) {
  Camera camera;
  camera.world_from_camera = world_from_camera_look_at(eye, target);
  camera.projection = Perspective::from_horizontal_fov_degrees(hfov_degrees);
  camera.film.width_px = camera.film.height_px = size;
  return camera;
}

}  // namespace obscura::testing
