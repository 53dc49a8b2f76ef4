#include "obscura/camera/intrinsics.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

Intrinsics intrinsics(const Camera& camera) {
  if (auto* c = std::get_if<CalibratedProjection>(&camera.projection)) {
    if (c->width_px == 0) return c->k;
    // K scales with the image: u + ½ = (u_cal + ½) · W / W_cal.
    double sx = double(camera.film.width_px) / c->width_px;
    double sy = double(camera.film.height_px) / c->height_px;
    return {.fx = c->k.fx * sx,
            .fy = c->k.fy * sy,
            .cx = (c->k.cx + 0.5) * sx - 0.5,
            .cy = (c->k.cy + 0.5) * sy - 0.5,
            .skew = c->k.skew * sx};
  }
  if (!std::holds_alternative<Perspective>(camera.projection))
    throw Error("camera.intrinsics", "K describes a perspective camera; this camera is " +
                                         std::string(projection_name(camera.projection)));
  // Raster = (window − min) · W / (max − min) with the window in tangents, and K's u = raster − ½.
  ScreenWindow w = camera.screen_window();
  Intrinsics k;
  k.fx = camera.film.width_px / (w.x_max - w.x_min);
  k.fy = camera.film.height_px / (w.y_max - w.y_min);
  k.cx = -w.x_min * k.fx - 0.5;
  k.cy = w.y_max * k.fy - 0.5;
  return k;
}

Camera camera_from_intrinsics(const Intrinsics& k, int width_px, int height_px,
                              double sensor_width_mm) {
  if (!(k.fx > 0)) throw Error("intrinsics.fx", "must be positive; got " + number_text(k.fx));
  if (!(k.fy > 0)) throw Error("intrinsics.fy", "must be positive; got " + number_text(k.fy));
  if (width_px <= 0 || height_px <= 0)
    throw Error("intrinsics resolution",
                "must be positive; got " + number_text(width_px) + "x" + number_text(height_px));
  Camera camera;
  camera.film.width_px = width_px;
  camera.film.height_px = height_px;
  camera.film.pixel_aspect = k.fy / k.fx;  // a pixel spans 1/fx by 1/fy tangent units
  Perspective p;
  p.sensor_fit = SensorFit::horizontal;
  p.sensor_width_mm = sensor_width_mm;
  p.sensor_height_mm = sensor_width_mm * height_px * camera.film.pixel_aspect / width_px;
  p.focal_length_mm = k.fx * sensor_width_mm / width_px;
  // The window's centre in tangents, then in units of the fitted (horizontal) film dimension,
  // which is W / fx tangent units wide.
  double centre_x = (0.5 * width_px - (k.cx + 0.5)) / k.fx;
  double centre_y = ((k.cy + 0.5) - 0.5 * height_px) / k.fy;
  double fitted = width_px / k.fx;
  p.lens_shift = {centre_x / fitted, centre_y / fitted};
  camera.projection = p;
  camera.validate();
  return camera;
}

}  // namespace obscura
