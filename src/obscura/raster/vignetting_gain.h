// The thin lens's vignetting (camera/vignetting.h) for the rasterizer: a per-pixel gain on the
// rendered film, the relative illumination at each pixel centre (Camera::relative_illumination:
// cos⁴θ if natural, times the share of the aperture the barrel leaves if mechanical), so the
// rasterizer's frame darkens towards the corners as the tracer's does. The tracer keeps or stops
// each lens sample's ray at the barrel, which also gives off-axis bokeh its cat-eye shape; the
// rasterizer's accumulated depth of field keeps whole-aperture bokeh and gets the same light.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/film/film.h"

namespace obscura::raster {

// Multiplies each pixel of `film` (the camera's crop) by the relative illumination at its
// centre; nothing without vignetting.
void apply_vignetting(Film& film, const Camera& camera);

}  // namespace obscura::raster
