// The value contract between scene data and the renderers: the largest coordinates and light
// values a scene, a camera or a calibration may hand them. Checked where values enter
// (Scene::validate, Camera::validate), so every door (files, command line, Python) refuses the
// same values with a message naming the field.
#pragma once

#include <string>

#include "obscura/math/number_text.h"

namespace obscura {

// The largest |coordinate|, in metres, of any world-space point: vertices after their instance
// transform, lights, the camera. Both renderers work in single precision, where a float at 1e7
// has a spacing of 1 (2^-24 relative): beyond 10,000 km (about the Earth's diameter) a scene of
// human scale cannot be resolved at all, ray offsets outgrow objects, and much further out
// (≈ 1.8e18) Embree asserts and aborts. A planet-scale scene belongs in a local frame anyway.
inline constexpr double kMaxWorldCoordinateM = 1e7;

// The largest emitted radiance (W·sr⁻¹·m⁻²), radiant intensity (W/sr) or irradiance (W/m²) a
// light may have. The sun's disc is about 2e7 W·sr⁻¹·m⁻²; 1e12 is far past any real source and
// keeps a light's power (× an area up to kMaxWorldCoordinateM², × 4π) finite in a float, which
// the light selection's distribution needs.
inline constexpr double kMaxLightValue = 1e12;

// "must be within ±1e7 m: …" for a coordinate of `value`.
inline std::string world_coordinate_message(double value) {
  return "is " + number_text(value) + " m; coordinates must be finite and within ±" +
         number_text(kMaxWorldCoordinateM) +
         " m (beyond that single-precision ray tracing cannot resolve the scene)";
}

}  // namespace obscura
