// The film's geometry as the camera sees it: resolution, pixel shape, the region to render and
// the tracer's reconstruction filter. (The film that stores samples is film/film.h.)
//
// Raster coordinates are pixels with (0, 0) at the top-left corner of the full image and pixel
// centres at half-integers. The crop window renders a region: its fractions are of the full
// image, top-left origin (pbrt's cropwindow; Blender's border measures y from the bottom). The
// image written is the crop's size: the region, not the full frame with black around it.
#pragma once

#include "obscura/camera/pixel_filter.h"
#include "obscura/math/bounds.h"

namespace obscura {

struct CropWindow {
  double x_min = 0, y_min = 0, x_max = 1, y_max = 1;  // in [0, 1], min < max
};

struct FilmGeometry {
  int width_px = 512, height_px = 512;  // > 0
  double pixel_aspect = 1;              // a pixel's width / height, > 0
  CropWindow crop;
  PixelFilter filter = BoxFilter{};

  // width·pixel_aspect / height: the image's shape on the sensor.
  double image_aspect() const { return width_px * pixel_aspect / height_px; }
  // The pixels the crop covers: [⌈W·x_min⌉, ⌈W·x_max⌉) × [⌈H·y_min⌉, ⌈H·y_max⌉) (as pbrt).
  Bounds2i crop_pixels() const;
};

// Throws obscura::Error naming the first invalid parameter and its value (zero resolution, a
// crop window outside [0, 1] or empty, a bad filter).
void validate(const FilmGeometry& film);

}  // namespace obscura
