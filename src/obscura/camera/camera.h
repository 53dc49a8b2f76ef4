// The camera: where it is, how it projects, and the film it exposes.
//
// For now a pinhole (perspective) camera given by its vertical field of view; the full camera
// model (thin lens, orthographic, shutter, exposure, filters) extends this description.
// Camera space: X right, Y up, looking down −Z. Raster space: pixels, (0,0) at the top-left
// corner of the image, pixel centres at half-integers.
#pragma once

#include "obscura/math/ray.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"

namespace obscura {

struct Camera {
  Transform world_from_camera;
  double vertical_fov_degrees = 40;  // in (0, 180)
  int width = 512, height = 512;     // film resolution in pixels, > 0

  // Throws obscura::Error naming the first invalid parameter.
  void validate() const;

  // The primary ray through raster point `film_point` (pixels); the direction is unit length.
  Ray generate_ray(Point2f film_point) const;
};

}  // namespace obscura
