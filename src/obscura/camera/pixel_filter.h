// Pixel reconstruction filters for the tracer: how much a sample at offset (dx, dy) pixels from a
// pixel's centre counts towards that pixel. All four are separable, f(dx, dy) = f(dx)·f(dy).
//
// The tracer uses filter importance sampling (Ernst et al. 2006; pbrt-v4's FilterSampler): each
// sample of pixel P is placed at P's centre plus an offset drawn with density ∝ |f|, and
// counts for P alone with weight f/pdf. A pixel's samples therefore never touch its neighbours,
// tiles stay independent and the image is deterministic at any thread count.
#pragma once

#include <string_view>
#include <variant>
#include <vector>

#include "obscura/math/vector.h"

namespace obscura {

struct BoxFilter {
  double radius_px = 0.5;  // > 0; 0.5 is one pixel's square
};
struct TentFilter {
  double radius_px = 1;  // > 0; f(x) = max(0, 1 − |x| / radius)
};
// exp(−x²/2σ²) − exp(−r²/2σ²), clamped at 0, so that it reaches zero at the radius (as pbrt).
struct GaussianFilter {
  double radius_px = 1.5;  // > 0
  double sigma_px = 0.5;   // > 0
};
// Mitchell & Netravali (1988), stretched so that its support [−2, 2] covers [−radius, radius].
// B = C = 1/3 is their recommendation; its negative lobes sharpen.
struct MitchellFilter {
  double radius_px = 2;  // > 0
  double b = 1.0 / 3, c = 1.0 / 3;
};

using PixelFilter = std::variant<BoxFilter, TentFilter, GaussianFilter, MitchellFilter>;

double filter_radius_px(const PixelFilter& f);
// The separable filter's value at an offset from the pixel centre, in pixels.
double evaluate(const PixelFilter& f, Vector2d offset_px);
// "box", "tent", "gaussian", "mitchell".
std::string_view filter_name(const PixelFilter& f);
// A filter by name with its default parameters; radius_px > 0 replaces the default radius.
// Throws obscura::Error naming the name or radius when invalid.
PixelFilter make_pixel_filter(std::string_view name, double radius_px = 0);
// Throws obscura::Error naming the first invalid parameter and its value.
void validate(const PixelFilter& f);

struct FilterSample {
  Vector2d offset_px;  // from the pixel centre, within the filter's radius
  double weight;       // f(offset) / pdf(offset): constant for box and tent, signed for Mitchell
};

// Draws offsets distributed as |f|: exactly for box and tent (inverse CDF), from a tabulated
// piecewise-constant CDF for Gaussian and Mitchell, the weight correcting for the table.
class FilterSampler {
 public:
  explicit FilterSampler(const PixelFilter& filter);
  FilterSample sample(Point2d u) const {
    // The box, the tracer's usual filter, inline: the render loop draws one offset per sample.
    if (box_radius_px_ > 0)
      return {{(2 * u.x - 1) * box_radius_px_, (2 * u.y - 1) * box_radius_px_}, 1.0};
    return sample_other(u);
  }

 private:
  FilterSample sample_other(Point2d u) const;

  struct Axis1D {
    double radius = 0;
    std::vector<double> values;  // f at bin centres (signed)
    std::vector<double> cdf;     // of |f| per bin, cdf[0] = 0, cdf.back() = 1
    double integral = 0;         // ∫|f| over [−radius, radius] by the table
  };
  double sample_axis(double u, double* pdf, double* value) const;

  PixelFilter filter_;
  double box_radius_px_ = 0;  // the box's radius when filter_ is one, else 0
  Axis1D table_;
};

}  // namespace obscura
