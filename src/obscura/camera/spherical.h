// Cameras that see more than a frustum: the equirectangular (latitude–longitude, 360° × 180°)
// panorama and the equidistant fisheye. Both map film points to directions in camera space
// (X right, Y up, looking down −Z) and back; the tracer uses them, the rasterizer cannot (no
// straight lines stay straight, so there is no projection matrix).
#pragma once

#include <optional>

#include "obscura/math/vector.h"

namespace obscura {

// Longitude φ = 2π·(x/W − ½) (0 straight ahead, +π/2 to the right), latitude
// θ = π·(½ − y/H) (+π/2 straight up): the image centre looks down −Z, the left and right edges
// look backwards (+Z), as an environment map seen from inside.
struct Equirectangular {};

// Equidistant fisheye: the angle from the optical axis grows linearly with the distance from the
// image centre, θ = r / R · fov/2, where R is the radius of the image circle, which touches the
// shorter side of the image (a circular fisheye); film points outside it see nothing.
struct Fisheye {
  double fov_degrees = 180;  // across the image circle, in (0, 360]
};

// Throws obscura::Error naming the value when fov_degrees is outside (0, 360].
void validate(const Fisheye& f);

// Unit direction (camera space) for film coordinates normalized to [0, 1]² (u right, v down).
Vector3d equirectangular_direction(Point2d uv);
// The inverse; `direction` need not be unit length (non-zero).
Point2d equirectangular_uv(Vector3d direction);

// `centered` is the film point relative to the image centre in units of the image circle's
// radius (+x right, +y up); nothing when it lies outside the circle.
std::optional<Vector3d> fisheye_direction(const Fisheye& f, Point2d centered);
std::optional<Point2d> fisheye_centered(const Fisheye& f, Vector3d direction);

}  // namespace obscura
