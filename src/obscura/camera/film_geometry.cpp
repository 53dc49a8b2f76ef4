#include "obscura/camera/film_geometry.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

Bounds2i FilmGeometry::crop_pixels() const {
  return {{int(std::ceil(width_px * crop.x_min)), int(std::ceil(height_px * crop.y_min))},
          {int(std::ceil(width_px * crop.x_max)), int(std::ceil(height_px * crop.y_max))}};
}

void validate(const FilmGeometry& film) {
  if (film.width_px <= 0 || film.height_px <= 0)
    throw Error("camera.resolution", "must be positive; got " + number_text(film.width_px) + "x" +
                                         number_text(film.height_px));
  if (!(film.pixel_aspect > 0) || !std::isfinite(film.pixel_aspect))
    throw Error("camera.pixel_aspect", "must be positive; got " + number_text(film.pixel_aspect));
  const CropWindow& c = film.crop;
  auto in_unit = [](double v) { return v >= 0 && v <= 1; };
  std::string crop_text = number_text(c.x_min) + "," + number_text(c.y_min) + "," +
                          number_text(c.x_max) + "," + number_text(c.y_max);
  if (!in_unit(c.x_min) || !in_unit(c.y_min) || !in_unit(c.x_max) || !in_unit(c.y_max))
    throw Error("camera.crop", "must lie within [0, 1]; got " + crop_text);
  Bounds2i pixels = film.crop_pixels();
  if (!(c.x_min < c.x_max && c.y_min < c.y_max) || pixels.min.x >= pixels.max.x ||
      pixels.min.y >= pixels.max.y)
    throw Error("camera.crop",
                "must cover at least one pixel (x0 < x1, y0 < y1); got " + crop_text);
  validate(film.filter);
}

}  // namespace obscura
