// The order in which every renderer draws a camera sample's numbers from its sampler: the film
// point (distributed as the pixel filter), the lens point, the time in the shutter (plus the
// pixel's rolling-shutter delay) and, in spectral mode, the number that picks the wavelengths —
// before anything a renderer draws for the light's path. One order for all is what lets two
// renderers (and a render split any way) see the same camera rays for the same seed.
//
// Numbers that cannot change the image are skipped, not drawn: the lens point without depth of
// field or a lens system, the time where nothing moves during the shutter (most of a sample's
// sampler cost where camera rays escape to the environment). Skipping keeps every later number
// where it was, so the image is the one drawing them would give.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/camera/pixel_filter.h"
#include "obscura/math/sampler.h"
#include "obscura/math/vector.h"

namespace obscura {

struct CameraSample {
  Point2d film_point;         // raster position in the full image, pixels
  double filter_weight = 1;   // the pixel filter's weight of this film point
  Point2f lens{0.5f, 0.5f};   // ∈ [0,1)², the lens centre where the lens does not matter
  double time_s = 0;          // in the shutter, with the pixel's readout delay
  float wavelength_u = 0.5f;  // spectral mode: the number that picks the wavelengths
};

class CameraSampleOrder {
 public:
  // `scene_moves`: something in the scene moves during the shutter. `camera` outlives this.
  CameraSampleOrder(const Camera& camera, bool scene_moves, bool spectral)
      : camera_(camera),
        filter_(camera.film.filter),
        lens_matters_(camera.uses_lens_samples()),
        time_matters_(scene_moves || camera.world_from_camera.is_animated()),
        spectral_(spectral),
        still_time_s_(camera.shutter.time_at(0.5)) {}

  // A rolling shutter exposes a pixel's sensor line later: every sample of the pixel takes its
  // line's delay (computed once per pixel).
  double pixel_delay_s(Point2i pixel) const {
    return camera_.readout_delay_s({pixel.x + 0.5, pixel.y + 0.5});
  }

  // The camera's numbers of one sample of `pixel` (full-image coordinates).
  CameraSample draw(Sampler& sampler, Point2i pixel, double delay_s) const {
    CameraSample s;
    const Point2f u_filter = sampler.next_2d();
    const FilterSample f = filter_.sample({u_filter.x, u_filter.y});
    s.film_point = {pixel.x + 0.5 + f.offset_px.x, pixel.y + 0.5 + f.offset_px.y};
    s.filter_weight = f.weight;
    if (lens_matters_)
      s.lens = sampler.next_2d();
    else
      sampler.skip_2d();
    if (time_matters_) {
      s.time_s = camera_.shutter.time_at(sampler.next_1d()) + delay_s;
    } else {
      sampler.skip_1d();
      s.time_s = still_time_s_ + delay_s;
    }
    if (spectral_) s.wavelength_u = sampler.next_1d();
    return s;
  }

 private:
  const Camera& camera_;
  FilterSampler filter_;
  bool lens_matters_, time_matters_, spectral_;
  double still_time_s_;
};

}  // namespace obscura
