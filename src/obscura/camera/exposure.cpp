#include "obscura/camera/exposure.h"

#include <cmath>
#include <iterator>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {
// ISO 12232 saturation-based speed: L_sat = 78 / (S · q) · N² / t with lens transmittance and
// vignetting q = 0.65; 78 / (100 · 0.65) = 1.2 at S = 100.
constexpr double kSaturationFactor = 78.0 / (100 * 0.65);
// Full- and third-stop markings, f/0.7 to f/64; marking i is 2^((i − 3)/6).
constexpr double kMarkedFNumbers[] = {
    0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.4, 1.6, 1.8, 2,  2.2, 2.5, 2.8, 3.2, 3.5, 4,  4.5, 5,  5.6, 6.3,
    7.1, 8,   9,   10,  11,  13,  14,  16,  18,  20, 22,  25,  29,  32,  36,  40, 45,  51, 57,  64};
}  // namespace

double stop_f_number(double marked) {
  for (size_t i = 0; i < std::size(kMarkedFNumbers); ++i)
    if (std::abs(marked - kMarkedFNumbers[i]) < 1e-9) return std::exp2((double(i) - 3) / 6);
  return marked;
}

double ev100(double f_number, double exposure_time_s, double iso) {
  return std::log2(f_number * f_number / exposure_time_s * 100 / iso);
}

double exposure_scale(const Exposure& e, double f_number, double exposure_time_s) {
  double compensation = std::exp2(e.compensation_ev);
  if (e.mode == ExposureMode::radiance) return compensation;
  double saturating_luminance =
      kSaturationFactor * std::exp2(ev100(stop_f_number(f_number), exposure_time_s, e.iso));
  return compensation / saturating_luminance;
}

void validate(const Exposure& e, double exposure_time_s) {
  // Beyond ±64 EV (a factor of 2^64) a float film overflows to Inf or flushes to 0.
  if (!std::isfinite(e.compensation_ev) || std::abs(e.compensation_ev) > 64)
    throw Error("camera.exposure_ev",
                "must be a finite EV within ±64; got " + number_text(e.compensation_ev));
  if (!(e.iso > 0) || !std::isfinite(e.iso))
    throw Error("camera.iso", "must be positive; got " + number_text(e.iso));
  if (e.mode == ExposureMode::physical && !(exposure_time_s > 0))
    throw Error("camera.shutter", "physical exposure needs the shutter open for some time; got " +
                                      number_text(exposure_time_s) + " s");
}

ExposureMode parse_exposure_mode(std::string_view text) {
  if (text == "radiance") return ExposureMode::radiance;
  if (text == "physical") return ExposureMode::physical;
  throw Error("exposure mode",
              "expected 'radiance' or 'physical'; got '" + std::string(text) + "'");
}

std::string_view exposure_mode_name(ExposureMode mode) {
  return mode == ExposureMode::physical ? "physical" : "radiance";
}

}  // namespace obscura
