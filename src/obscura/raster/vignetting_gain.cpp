#include "obscura/raster/vignetting_gain.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace obscura::raster {

namespace {

// Each pixel of `film` (the crop `crop` of the image) times gain(its centre, raster coordinates);
// rows in parallel, each pixel independent of the others.
template <typename Gain>
void scale_pixels(Film& film, const Bounds2i& crop, const Gain& gain) {
  tbb::parallel_for(tbb::blocked_range<int>(0, film.height()), [&](const tbb::blocked_range<int>&
                                                                       r) {
    for (int y = r.begin(); y < r.end(); ++y)
      for (int x = 0; x < film.width(); ++x)
        film.scale_pixel({x, y}, float(gain(Point2d(crop.min.x + x + 0.5, crop.min.y + y + 0.5))));
  });
}

}  // namespace

void apply_vignetting(Film& film, const Camera& camera, bool barrel_in_frames) {
  if (!camera.lens.vignetting.any()) return;
  if (barrel_in_frames && !camera.lens.vignetting.natural) return;
  Camera natural_only = camera;
  if (barrel_in_frames) natural_only.lens.vignetting.barrel_diameter_mm = 0;
  const PreparedCamera prepared = natural_only.prepare();
  // Per pixel, not interpolated: the barrel's share changes quickly where a strong barrel cuts
  // in, faster than an interpolated grid follows.
  scale_pixels(film, camera.film.crop_pixels(),
               [&](Point2d centre) { return prepared.relative_illumination(centre); });
}

void apply_relative_illumination(Film& film, const FittedLensCamera& fitted) {
  scale_pixels(film, fitted.camera.film.crop_pixels(),
               [&](Point2d centre) { return fitted.relative_illumination(centre); });
}

}  // namespace obscura::raster
