// Scenes and helpers for the REYES tests: unlit materials (a pixel's value is then the covered
// fraction of its samples, whatever the lights), cameras, and a direct call of reyes::render.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "obscura/camera/frames.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/reyes/render.h"
#include "obscura/reyes/reyes_scene.h"
#include "obscura/scene/scene.h"
#include "trace/trace_test_scenes.h"

namespace obscura::testing {

inline Material unlit_material(Rgb color, float alpha = 1, AlphaMode mode = AlphaMode::kOpaque) {
  Material m;
  m.name = "unlit";
  MetallicRoughnessMaterial mr;
  mr.base_color = color;
  mr.alpha = alpha;
  mr.unlit = true;
  m.model = mr;
  m.alpha_mode = mode;
  return m;
}

inline Instance make_instance(const char* name, uint32_t mesh) {
  Instance instance;
  instance.name = name;
  instance.mesh = mesh;
  return instance;
}

inline Light make_light(const char* name, LightModel model) {
  Light light;
  light.name = name;
  light.model = model;
  return light;
}

// An orthographic camera on +Z looking at the origin, `view_height_m` tall.
inline Camera orthographic_camera(double view_height_m, int width, int height) {
  Camera camera;
  camera.world_from_camera = world_from_camera_look_at({0, 0, 10}, {0, 0, 0});
  camera.projection = Orthographic{.view_height_m = view_height_m, .view_width_m = std::nullopt};
  camera.film.width_px = width;
  camera.film.height_px = height;
  camera.film.filter = BoxFilter{0.5};
  return camera;
}

// A disk of radius r in the plane z = `z`, facing +Z, as a fan of `segments` triangles.
inline Mesh make_disk(float r, float z, int segments, uint32_t material) {
  Mesh mesh;
  mesh.name = "disk";
  mesh.material = material;
  mesh.positions.push_back({0, 0, z});
  for (int s = 0; s < segments; ++s) {
    const double phi = 2 * std::numbers::pi * s / segments;
    mesh.positions.push_back({float(r * std::cos(phi)), float(r * std::sin(phi)), z});
  }
  for (int s = 0; s < segments; ++s)
    mesh.indices.insert(mesh.indices.end(), {0, uint32_t(1 + s), uint32_t(1 + (s + 1) % segments)});
  return mesh;
}

struct ReyesFrame {
  Film film;
  std::optional<AovBuffers> aovs;
  reyes::ReyesStats stats;
};

inline ReyesFrame render_reyes(const Scene& scene, const Camera& camera,
                               const reyes::ReyesSettings& settings, bool aovs = false) {
  const reyes::ReyesScene compiled(scene);
  const Bounds2i crop = camera.film.crop_pixels();
  ReyesFrame frame{Film(crop.width(), crop.height()), std::nullopt, {}};
  if (aovs) frame.aovs.emplace(crop.width(), crop.height(), false);
  frame.stats =
      reyes::render(compiled, camera, settings, frame.film, frame.aovs ? &*frame.aovs : nullptr);
  return frame;
}

// A pixel's value in units of an unlit white surface's.
inline double coverage(const ReyesFrame& frame, const Camera& camera, int x, int y) {
  return frame.film.pixel({x, y}).r / camera.exposure_scale();
}

}  // namespace obscura::testing
