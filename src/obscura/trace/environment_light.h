// Light from infinitely far away in every direction: a constant radiance or an equirectangular
// (latitude-longitude) map, importance sampled in proportion to luminance × sin θ so that bright
// regions (the sun in a sky map) are found by light sampling rather than by chance.
//
// Map layout: row 0 looks up (+Y of the environment frame), the centre column looks along −Z,
// and u grows towards +X; world_from_environment orients the frame in the scene.
#pragma once

#include <optional>

#include "obscura/color/rgb.h"
#include "obscura/film/image.h"
#include "obscura/math/distribution.h"
#include "obscura/math/transform.h"

namespace obscura {

struct EnvironmentSample {
  Vector3f wi;  // world, unit, towards the environment
  Rgb radiance;
  float pdf = 0;  // solid angle
};

class EnvironmentLight {
 public:
  // The same radiance from every direction.
  explicit EnvironmentLight(Rgb radiance);
  // An RGB(A) lat-long map of linear radiance, scaled by `scale`. Throws obscura::Error for an
  // empty image or one with fewer than 3 channels.
  EnvironmentLight(const Image& map, Rgb scale, const Transform& world_from_environment);

  Rgb radiance(Vector3f world_direction) const;
  EnvironmentSample sample(Point2f u) const;
  float pdf(Vector3f world_direction) const;
  // Average luminance over the sphere: what light selection weighs the environment by.
  float average_luminance() const { return average_luminance_; }
  // The same radiance from every direction (no map).
  bool is_constant() const { return !map_; }

 private:
  Point2f uv_from_direction(Vector3f local) const;
  Vector3f direction_from_uv(Point2f uv) const;
  Rgb lookup(Point2f uv) const;

  Rgb constant_;
  std::optional<Image> map_;
  Transform world_from_environment_;
  Distribution2D distribution_;
  float average_luminance_ = 0;
};

}  // namespace obscura
