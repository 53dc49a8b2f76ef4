// All the scene's emitters behind one interface for the integrators: one light is chosen in
// proportion to an estimate of its power, then sampled. Area lights are the emissive triangles
// (area_lights.h), the environment is infinitely far (environment_light.h), point, spot and
// directional lights have no area (punctual_light.h).
#pragma once

#include <limits>
#include <optional>

#include "obscura/trace/area_lights.h"
#include "obscura/trace/environment_light.h"
#include "obscura/trace/punctual_light.h"

namespace obscura {

struct LightSample {
  Vector3f wi;  // world, unit, from the shaded point towards the light
  float distance = std::numeric_limits<float>::infinity();  // to the light point
  Rgb radiance;           // arriving along −wi (for delta lights: irradiance-like intensity/d²)
  float pdf = 0;          // solid angle density, the light's selection probability included
  bool is_delta = false;  // a point or directional light: no BSDF sample can hit it
  // For lights at a finite distance: the point sampled and the light's normal there (zero for
  // point lights), so that shadow rays can stop just in front of the light's surface.
  Point3f position;
  Normal3f normal;
  // For spectral mode: a blackbody area light's spectral shape (radiance is then its RGB
  // equivalent); null where the spectrum is the RGB radiance lifted.
  const BlackbodySpectrum* spectrum = nullptr;
};

// Which lights a light sample is drawn from. `kAll` for integrators that find light only by
// sampling it (Whitted, light-only paths). `kForMis` for a path tracer that also follows BSDF
// samples and weighs the two by MIS: it leaves out a constant environment, which the BSDF's own
// importance sampling (cosine, GGX visible normals) finds with a density closer to the integrand
// than any light sample can — uniform directions only add variance there, and their MIS weight
// takes part of the BSDF samples' share. An environment map stays in both.
enum class LightSampling { kAll, kForMis };

class LightSet {
 public:
  LightSet() = default;
  // `scene_radius` (m) sizes the disk through which distant light enters the scene.
  LightSet(AreaLights area_lights, std::optional<EnvironmentLight> environment,
           std::vector<PunctualLight> punctual, float scene_radius);

  bool empty(LightSampling which = LightSampling::kAll) const {
    return selection(which).size() == 0;
  }
  std::optional<LightSample> sample(Point3f p, float u_select, Point2f u,
                                    LightSampling which = LightSampling::kAll) const;

  // Solid-angle density with which sample() from `p` would have produced the point `light_point`
  // on triangle `primitive` of mesh `mesh`.
  float pdf_area_light(Point3f p, uint32_t mesh, uint32_t primitive, Point3f light_point,
                       LightSampling which = LightSampling::kAll) const;
  // Solid-angle density with which sample() would have chosen the environment direction `wi`
  // (0 when `which` leaves the environment out).
  float pdf_environment(Vector3f wi, LightSampling which = LightSampling::kAll) const;

  const AreaLights& area_lights() const { return area_; }
  const EnvironmentLight* environment() const { return environment_ ? &*environment_ : nullptr; }
  const std::vector<PunctualLight>& punctual() const { return punctual_; }

 private:
  // Selection entries: 0 = all area lights, 1 = the environment, 2 + i = punctual light i.
  enum Entry : int { kArea, kEnvironment, kFirstPunctual };
  AreaLights area_;
  std::optional<EnvironmentLight> environment_;
  std::vector<PunctualLight> punctual_;
  const Distribution1D& selection(LightSampling which) const {
    return which == LightSampling::kAll ? selection_all_ : selection_for_mis_;
  }
  Distribution1D selection_all_;
  Distribution1D selection_for_mis_;  // selection_all_ without a constant environment
};

}  // namespace obscura
