#include "obscura/trace/punctual_light.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "obscura/math/sampling.h"

namespace obscura {

PunctualLight PunctualLight::point(Point3f position, Rgb intensity) {
  return {.kind = Kind::kPoint, .position = position, .intensity = intensity};
}

PunctualLight PunctualLight::spot(Point3f position, Vector3f direction, Rgb intensity,
                                  float inner_radians, float outer_radians) {
  return {.kind = Kind::kSpot,
          .position = position,
          .direction = normalize(direction),
          .intensity = intensity,
          .cos_inner = std::cos(inner_radians),
          .cos_outer = std::cos(outer_radians)};
}

PunctualLight PunctualLight::directional(Vector3f direction, Rgb irradiance) {
  PunctualLight light;
  light.kind = Kind::kDirectional;
  light.direction = normalize(direction);
  light.intensity = irradiance;
  return light;
}

float PunctualLight::spot_falloff(Vector3f w) const {
  float c = dot(w, direction);
  float scale = 1 / std::max(1e-3f, cos_inner - cos_outer);
  float t = std::clamp((c - cos_outer) * scale, 0.f, 1.f);
  return t * t;
}

float PunctualLight::power(float scene_radius) const {
  float l = luminance(intensity);
  switch (kind) {
    case Kind::kPoint:
      return 4 * kPi * l;
    case Kind::kSpot:
      return 2 * kPi * (1 - 0.5f * (cos_inner + cos_outer)) * l;
    case Kind::kDirectional:
      return kPi * scene_radius * scene_radius * l;
  }
  return 0;
}

std::optional<PunctualLight::Incident> PunctualLight::incident(Point3f p) const {
  if (kind == Kind::kDirectional)
    return Incident{-direction, std::numeric_limits<float>::infinity(), intensity};
  Vector3f to_light = position - p;
  float d2 = length_squared(to_light);
  if (d2 <= 0) return std::nullopt;
  float d = std::sqrt(d2);
  Vector3f wi = to_light / d;
  float falloff = kind == Kind::kSpot ? spot_falloff(-wi) : 1.f;
  if (falloff <= 0) return std::nullopt;
  return Incident{wi, d, intensity * (falloff / d2)};
}

}  // namespace obscura
