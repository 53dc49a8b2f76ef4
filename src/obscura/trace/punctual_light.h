// Lights without area, as the tracer samples them: point and spot lights (a position) and
// directional lights (a direction). Their light arrives along one direction only, so only light
// sampling can find it (delta lights, no MIS). Units follow KHR_lights_punctual: intensity in
// W/sr (candela-like), directional irradiance in W/m².
#pragma once

#include <optional>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"

namespace obscura {

struct PunctualLight {
  enum class Kind { kPoint, kSpot, kDirectional };
  Kind kind = Kind::kPoint;
  Point3f position;              // point, spot
  Vector3f direction{0, -1, 0};  // spot: where the cone points; directional: where light travels
  Rgb intensity{1.f};            // point, spot: W/sr (on the axis); directional: irradiance W/m²
  float cos_inner = 1, cos_outer = 0;  // spot: full inside the inner cone, none outside the outer

  static PunctualLight point(Point3f position, Rgb intensity);
  // Angles in radians, 0 ≤ inner < outer ≤ π/2.
  static PunctualLight spot(Point3f position, Vector3f direction, Rgb intensity,
                            float inner_radians, float outer_radians);
  static PunctualLight directional(Vector3f direction, Rgb irradiance);

  // The spot's angular falloff towards world direction w from the light (1 on the axis): a
  // smooth t² ramp between the cones, as glTF viewers do.
  float spot_falloff(Vector3f w) const;
  // Emitted power's luminance (W), for light selection; `scene_radius` sizes a directional
  // light's beam.
  float power(float scene_radius) const;

  struct Incident {
    Vector3f wi;     // unit, from the shaded point towards the light
    float distance;  // ∞ for directional lights
    Rgb radiance;    // arriving irradiance-like term (I·falloff/d², or E)
  };
  std::optional<Incident> incident(Point3f p) const;
};

}  // namespace obscura
