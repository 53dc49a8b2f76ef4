#include "obscura/raster/vignetting_gain.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace obscura::raster {

void apply_vignetting(Film& film, const Camera& camera, bool barrel_in_frames) {
  if (!camera.lens.vignetting.any()) return;
  if (barrel_in_frames && !camera.lens.vignetting.natural) return;
  Camera natural_only = camera;
  if (barrel_in_frames) natural_only.lens.vignetting.barrel_diameter_mm = 0;
  const PreparedCamera prepared = natural_only.prepare();
  const Bounds2i crop = camera.film.crop_pixels();
  // Per pixel: the barrel's share changes quickly where a strong barrel cuts in, faster than an
  // interpolated grid follows, and each pixel is independent of the others.
  tbb::parallel_for(tbb::blocked_range<int>(0, film.height()),
                    [&](const tbb::blocked_range<int>& r) {
                      for (int y = r.begin(); y < r.end(); ++y)
                        for (int x = 0; x < film.width(); ++x) {
                          Point2d centre(crop.min.x + x + 0.5, crop.min.y + y + 0.5);
                          film.scale_pixel({x, y}, float(prepared.relative_illumination(centre)));
                        }
                    });
}

void apply_relative_illumination(Film& film, const FittedLensCamera& fitted) {
  const Bounds2i crop = fitted.camera.film.crop_pixels();
  tbb::parallel_for(tbb::blocked_range<int>(0, film.height()),
                    [&](const tbb::blocked_range<int>& r) {
                      for (int y = r.begin(); y < r.end(); ++y)
                        for (int x = 0; x < film.width(); ++x) {
                          Point2d centre(crop.min.x + x + 0.5, crop.min.y + y + 0.5);
                          film.scale_pixel({x, y}, float(fitted.relative_illumination(centre)));
                        }
                    });
}

}  // namespace obscura::raster
