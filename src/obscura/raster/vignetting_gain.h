// The thin lens's vignetting (camera/vignetting.h) for the rasterizer: a per-pixel gain on the
// rendered film, the relative illumination at each pixel centre (Camera::relative_illumination:
// cos⁴θ if natural, times the share of the aperture the barrel leaves if mechanical), so the
// rasterizer's frame darkens towards the corners as the tracer's does. The tracer keeps or stops
// each lens sample's ray at the barrel, which also gives off-axis bokeh its cat-eye shape; the
// rasterizer's accumulated depth of field keeps whole-aperture bokeh and gets the same light.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/camera/lens_system_fit.h"
#include "obscura/film/film.h"

namespace obscura::raster {

// Multiplies each pixel of `film` (the camera's crop) by the relative illumination at its
// centre; nothing without vignetting. `barrel_in_frames`: the frames were accumulated through
// jittered lens points with the barrel applied per lens point (accumulation.h), so only the
// natural cos⁴ part remains to apply.
void apply_vignetting(Film& film, const Camera& camera, bool barrel_in_frames = false);

// A lens system's relative illumination, as its fitted camera measured it (the mean of the
// tracer's ray weights at each image height, interpolated): each pixel of `film` (the camera's
// crop) times the value at its centre. This carries the lens's cos⁴ and mechanical vignetting
// and its exposure at the focus distance, so the rasterizer's frame is as bright as the
// tracer's, centre and corners.
void apply_relative_illumination(Film& film, const FittedLensCamera& fitted);

}  // namespace obscura::raster
