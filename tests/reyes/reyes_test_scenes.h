// Scenes and helpers for the REYES tests: unlit materials (a pixel's value is then the covered
// fraction of its samples, whatever the lights), cameras, and a direct call of reyes::render.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "obscura/camera/frames.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/film/image.h"
#include "obscura/render/frame_settings.h"
#include "obscura/render/render_frame.h"
#include "obscura/render/renderer.h"
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

// Cracks: pixels deep inside object 0 in `traced_ids` (it and its eight neighbours hit it) that
// the REYES frame does not cover completely. Both images are of `camera`.
struct Cracks {
  int inside = 0, cracked = 0;
};
inline Cracks count_cracks(const Image& traced_ids, const ReyesFrame& frame, const Camera& camera) {
  Cracks c;
  for (int y = 1; y + 1 < traced_ids.height; ++y)
    for (int x = 1; x + 1 < traced_ids.width; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) all = all && traced_ids.at(x + dx, y + dy, 0) == 0;
      if (!all) continue;
      ++c.inside;
      c.cracked += coverage(frame, camera, x, y) < 0.999;
    }
  return c;
}

// The id AOV of one sample per pixel at the pixel centre (a filter too narrow to move it).
inline Image centre_ids(const Scene& scene, Camera camera, const char* renderer) {
  camera.film.filter = BoxFilter{1e-6};
  FrameSettings settings{.renderer = renderer_named(renderer), .samples_per_pixel = 1};
  settings.reyes.pixel_samples = 1;
  const RenderedFrame frame = render_frame(scene, camera, settings, true);
  return frame.aovs->id();
}

// Pixels whose ids differ (≤ 0.1 %, returned), and whether each lies within 1 px of a silhouette
// in `reference`.
inline int expect_same_coverage(const Image& reyes, const Image& reference, const char* what) {
  int differ = 0, away = 0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      if (reyes.at(x, y, 0) == reference.at(x, y, 0)) continue;
      ++differ;
      bool edge = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = std::clamp(x + dx, 0, reference.width - 1);
          const int v = std::clamp(y + dy, 0, reference.height - 1);
          edge = edge || reference.at(u, v, 0) != reference.at(x, y, 0);
        }
      away += !edge;
    }
  const double share = double(differ) / (reference.width * reference.height);
  EXPECT_LE(share, 0.001) << what << ": " << differ << " pixels differ";
  EXPECT_EQ(away, 0) << what << ": differing pixels away from any silhouette";
  return differ;
}

}  // namespace obscura::testing
