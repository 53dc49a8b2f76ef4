#include "obscura/camera/exposure_program.h"

#include <algorithm>
#include <cmath>

namespace obscura {

namespace {
// Program limits in APEX units: Av = 2·log₂ N, Tv = −log₂ t. f/1.4 and f/16 as the series
// values the exposure counts with (stop_f_number: f/1.4 is √2), so the settings' EV is exact.
constexpr double kAvMin = 1, kAvMax = 8;
const double kTvHandheld = std::log2(30.0), kTvFastest = std::log2(8000.0);
constexpr double kMaxIsoStops = 6;  // ISO 100 → 6400
}  // namespace

ExposureSettings program_exposure(double ev, std::optional<double> fixed_f_number) {
  double av = fixed_f_number ? 2 * std::log2(*fixed_f_number) : std::clamp(ev / 2, kAvMin, kAvMax);
  double tv = ev - av;
  if (!fixed_f_number) {
    if (tv > kTvFastest) {  // too bright for the shutter: stop down (beyond f/16 if need be)
      av = ev - kTvFastest;
      tv = kTvFastest;
    } else if (tv < kTvHandheld) {  // too dark to hold: open up first
      av = std::max(kAvMin, ev - kTvHandheld);
      tv = ev - av;
    }
  }
  double gain_stops = 0;
  if (tv < kTvHandheld) {  // then raise the ISO, then expose longer
    gain_stops = std::min(kMaxIsoStops, kTvHandheld - tv);
    tv += gain_stops;
  }
  ExposureSettings s;
  s.f_number = std::exp2(av / 2);
  s.exposure_time_s = std::exp2(-tv);
  s.iso = 100 * std::exp2(gain_stops);
  return s;
}

}  // namespace obscura
