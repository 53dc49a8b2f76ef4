// Test scenes and cameras for camera geometry: white emitting shapes on black, and an integrator
// that shows them as exactly that (1 where a camera ray meets a surface, 0 elsewhere), so a pixel's
// value is the fraction of it the shapes cover and edges can be located to a small fraction of a
// pixel.
#pragma once

#include <string>

#include "obscura/camera/camera.h"
#include "obscura/scene/scene.h"
#include "obscura/trace/integrator.h"
#include "obscura/trace/trace_scene.h"

namespace obscura::test {

// A scene named `name` with one white emitting material (index 0) and no meshes yet.
inline Scene white_on_black(const std::string& name) {
  Scene scene;
  scene.name = name;
  Material white;
  white.name = "white";
  white.model = EmissiveMaterial{};
  white.emission = Rgb(1);
  scene.materials = {white};
  return scene;
}

// A camera with projection `p` on a width × height film, clipping nothing a test puts in view.
inline Camera calibrated_camera(const CalibratedProjection& p, int width, int height) {
  Camera c;
  c.projection = p;
  c.film.width_px = width;
  c.film.height_px = height;
  c.near_m = 1e-3;
  c.far_m = 1e6;
  c.validate();
  return c;
}

class FirstHitWhite final : public Integrator {
 public:
  Rgb radiance(const TraceScene& scene, const Ray& ray, Sampler&, RayCounts& counts,
               FirstHit*) const override {
    ++counts.camera;
    return scene.occluded(ray) ? Rgb(1) : Rgb(0);
  }
};

}  // namespace obscura::test
