#include "obscura/trace/environment_light.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "obscura/math/error.h"
#include "obscura/math/safe_index.h"
#include "obscura/math/sampling.h"

namespace obscura {

EnvironmentLight::EnvironmentLight(Rgb radiance)
    : constant_(radiance), average_luminance_(luminance(radiance)) {}

EnvironmentLight::EnvironmentLight(const Image& map, Rgb scale,
                                   const Transform& world_from_environment)
    : constant_(scale), map_(map), world_from_environment_(world_from_environment) {
  if (map.width <= 0 || map.height <= 0 || map.channels < 3)
    throw Error("environment map", "needs an RGB image; got " + std::to_string(map.width) + "x" +
                                       std::to_string(map.height) + " with " +
                                       std::to_string(map.channels) + " channels");
  // Weight each texel by its luminance and by sin θ, the lat-long map's area distortion.
  std::vector<float> weights(size_t(map.width) * map.height);
  double total = 0, solid_angle = 0;
  for (int y = 0; y < map.height; ++y) {
    float sin_theta = std::sin(kPi * (y + 0.5f) / map.height);
    for (int x = 0; x < map.width; ++x) {
      float l = std::max(0.f, luminance(map.rgb(x, y) * scale));
      weights[size_t(y) * map.width + x] = l * sin_theta;
      total += double(l) * sin_theta;
      solid_angle += sin_theta;
    }
  }
  average_luminance_ = solid_angle > 0 ? float(total / solid_angle) : 0.f;
  distribution_ = Distribution2D(weights, map.width, map.height);
}

Point2f EnvironmentLight::uv_from_direction(Vector3f d) const {
  float theta = std::atan2(std::sqrt(d.x * d.x + d.z * d.z), d.y);  // better than acos near poles
  float phi = std::atan2(d.x, -d.z);  // 0 along −Z, growing towards +X
  float u = 0.5f + phi * (0.5f * kInvPi);
  return {u - std::floor(u), theta * kInvPi};
}

Vector3f EnvironmentLight::direction_from_uv(Point2f uv) const {
  float phi = 2 * kPi * (uv.x - 0.5f), theta = kPi * uv.y;
  float sin_theta = std::sin(theta);
  return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

Rgb EnvironmentLight::lookup(Point2f uv) const {
  // A NaN direction (from a NaN normal or a light at 1e308) reads texel 0, not INT_MIN.
  int x = cell_index(uv.x * map_->width, map_->width);
  int y = cell_index(uv.y * map_->height, map_->height);
  return map_->rgb(x, y) * constant_;
}

Rgb EnvironmentLight::radiance(Vector3f world_direction) const {
  if (!map_) return constant_;
  Vector3f local = normalize(inverse(world_from_environment_)(world_direction));
  return lookup(uv_from_direction(local));
}

EnvironmentSample EnvironmentLight::sample(Point2f u) const {
  if (!map_) {
    Vector3f wi = sample_uniform_sphere(u);
    return {wi, constant_, uniform_sphere_pdf()};
  }
  float pdf_uv;
  Point2f uv = distribution_.sample(u, &pdf_uv);
  Vector3f local = direction_from_uv(uv);
  float sin_theta = std::sqrt(local.x * local.x + local.z * local.z);
  if (sin_theta <= 0 || pdf_uv <= 0) return {local, Rgb(), 0};
  // dω = 2π² sin θ du dv.
  float pdf = pdf_uv / (2 * kPi * kPi * sin_theta);
  return {normalize(world_from_environment_(local)), lookup(uv), pdf};
}

float EnvironmentLight::pdf(Vector3f world_direction) const {
  if (!map_) return uniform_sphere_pdf();
  Vector3f local = normalize(inverse(world_from_environment_)(world_direction));
  Point2f uv = uv_from_direction(local);
  float sin_theta = std::sqrt(local.x * local.x + local.z * local.z);
  if (sin_theta <= 0) return 0;
  return distribution_.pdf(uv) / (2 * kPi * kPi * sin_theta);
}

}  // namespace obscura
