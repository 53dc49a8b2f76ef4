#include "obscura/film/metering.h"

#include <cmath>
#include <string>

#include "obscura/math/request_error.h"

namespace obscura {

namespace {

// Rec.709 luminance weights (the Y row of its RGB → XYZ matrix, rounded as BT.709 prints it).
double luminance(const Image& film, int x, int y) {
  double l = 0.2126 * film.at(x, y, 0) + 0.7152 * film.at(x, y, 1) + 0.0722 * film.at(x, y, 2);
  return std::isfinite(l) && l > 0 ? l : 0;
}

// Whether pixel (x, y)'s centre lies in the central disc of radius r pixels.
bool in_disc(const Image& film, int x, int y, double r) {
  const double dx = x + 0.5 - film.width / 2.0, dy = y + 0.5 - film.height / 2.0;
  return dx * dx + dy * dy <= r * r;
}

}  // namespace

MeteringMode parse_metering_mode(std::string_view text) {
  if (text == "average") return MeteringMode::kAverage;
  if (text == "center-weighted" || text == "centre-weighted") return MeteringMode::kCenterWeighted;
  if (text == "spot") return MeteringMode::kSpot;
  throw RequestError("metering",
                     "expected average, center-weighted or spot; got '" + std::string(text) + "'");
}

std::string_view metering_mode_name(MeteringMode mode) {
  switch (mode) {
    case MeteringMode::kAverage:
      return "average";
    case MeteringMode::kCenterWeighted:
      return "center-weighted";
    case MeteringMode::kSpot:
      return "spot";
  }
  return "average";
}

double metered_luminance(const Image& film, MeteringMode mode) {
  if (film.channels < 3 || film.width <= 0 || film.height <= 0)
    throw Error("metering", "needs an RGB image");
  const double r = mode == MeteringMode::kSpot
                       ? std::sqrt(0.03 * film.width * film.height / std::acos(-1.0))
                       : film.height / 4.0;
  double inside = 0, outside = 0;
  long n_inside = 0, n_outside = 0;
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x) {
      const double l = luminance(film, x, y);
      if (mode != MeteringMode::kAverage && in_disc(film, x, y, r))
        inside += l, ++n_inside;
      else
        outside += l, ++n_outside;
    }
  const double mean_in = n_inside ? inside / double(n_inside) : 0;
  const double mean_out = n_outside ? outside / double(n_outside) : mean_in;
  switch (mode) {
    case MeteringMode::kAverage:
      return mean_out;
    case MeteringMode::kCenterWeighted:
      return n_inside ? 0.75 * mean_in + 0.25 * mean_out : mean_out;
    case MeteringMode::kSpot:
      // A frame too small for the disc to hold a pixel centre meters its centre pixel.
      return n_inside ? mean_in : luminance(film, film.width / 2, film.height / 2);
  }
  return mean_out;
}

double metered_ev100(double luminance_cd_m2) {
  return std::log2(luminance_cd_m2 * 100 / kIso2720K);
}

}  // namespace obscura
