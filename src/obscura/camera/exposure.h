// Exposure: the factor between the radiance reaching the camera and the value the film records.
//
// radiance mode (default): the film records scene radiance unscaled, times 2^compensation_ev,
//   so renders compare directly with pbrt's and Cycles'.
// physical mode: exposure time t, f-number N and ISO S combine as a camera's do, ∝ t·S / N²,
//   calibrated with the saturation-based sensitivity of ISO 12232 (as Frostbite and Filament):
//     EV100 = log2(N² / t · 100 / S)
//     scale = 2^compensation_ev / (1.2 · 2^EV100)  =  2^compensation_ev · t·S / (120 · N²)
//   where 1.2 = 78 / (100 · 0.65): the luminance (cd/m²) that just saturates the sensor is
//   1.2 · 2^EV100 and maps to 1.0. Sunny-16 (f/16, 1/100 s, ISO 100: EV100 = 14.6) saturates
//   at about 30 700 cd/m². One stop more aperture, time or ISO doubles the value.
#pragma once

#include <string_view>

namespace obscura {

enum class ExposureMode { radiance, physical };

struct Exposure {
  ExposureMode mode = ExposureMode::radiance;
  double compensation_ev = 0;  // both modes: scales by 2^EV
  double iso = 100;            // S > 0, physical mode
};

// The f-numbers engraved on lenses are rounded members of the series 2^(k/6), a third of a stop
// apart (full stops are every third: f/2.8 is 2^(3/2) = 2.828, f/11 is 11.31, f/22 is 22.63). This
// returns the exact series value for an engraved full- or third-stop marking from f/0.7 to f/64
// and any other value unchanged, so that f/2.8 → f/4 is exactly one stop, as a light meter
// counts it. Used by the physical exposure only.
double stop_f_number(double marked_f_number);
// EV100 = log2(N² / t · 100 / S), with N as given. Preconditions: all positive.
double ev100(double f_number, double exposure_time_s, double iso);
// The factor applied to radiance. `f_number` (through stop_f_number) and `exposure_time_s`
// matter in physical mode only.
double exposure_scale(const Exposure& e, double f_number, double exposure_time_s);

// Throws obscura::Error naming the first invalid value. Physical mode needs a shutter that
// stays open (exposure_time_s > 0).
void validate(const Exposure& e, double exposure_time_s);
// "radiance" or "physical"; throws obscura::Error naming the value otherwise.
ExposureMode parse_exposure_mode(std::string_view text);
std::string_view exposure_mode_name(ExposureMode mode);

}  // namespace obscura
