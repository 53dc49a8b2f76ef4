// Small scenes for the integrator tests, built in code.
#pragma once

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "obscura/camera/frames.h"
#include "obscura/math/error.h"
#include "obscura/scene/scene.h"

namespace obscura::testing {

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
inline Camera make_camera(Point3d eye, Point3d target, int size, double hfov_degrees) {
  Camera camera;
  camera.world_from_camera = world_from_camera_look_at(eye, target);
  camera.projection = Perspective::from_horizontal_fov_degrees(hfov_degrees);
  camera.film.width_px = camera.film.height_px = size;
  return camera;
}

// The objects of a Wavefront OBJ file with triangular faces ("o", "v", "f", "usemtl"); each
// object becomes a mesh whose material is looked up by name in `materials`.
inline Scene read_obj_triangles(const std::string& path,
                                const std::map<std::string, uint32_t>& materials) {
  std::ifstream in(path);
  if (!in) throw Error(path, "cannot open");
  Scene scene;
  std::vector<Point3f> positions;
  std::map<uint32_t, uint32_t> local;  // global vertex index → index in the current mesh
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "o") {
      scene.meshes.emplace_back();
      words >> scene.meshes.back().name;
      local.clear();
    } else if (tag == "v") {
      Point3f p;
      words >> p.x >> p.y >> p.z;
      positions.push_back(p);
    } else if (tag == "usemtl") {
      std::string name;
      words >> name;
      scene.meshes.back().material = materials.at(name);
    } else if (tag == "f") {
      Mesh& mesh = scene.meshes.back();
      std::string vertex;
      while (words >> vertex) {
        auto global = uint32_t(std::stoul(vertex) - 1);
        auto [it, inserted] = local.try_emplace(global, uint32_t(mesh.positions.size()));
        if (inserted) mesh.positions.push_back(positions.at(global));
        mesh.indices.push_back(it->second);
      }
    }
  }
  return scene;
}

}  // namespace obscura::testing
