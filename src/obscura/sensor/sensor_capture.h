// The raw sensor: from a finished film (linear Rec.709, the renderers' units) to the digital
// numbers a camera's ADC reports, with every noise source, and the ground truth beside them.
//
// Per pixel (x, y) under CFA colour k (docs/sensor.md has the derivation):
//   H        = film · lux_seconds_per_film            focal-plane exposure, lux·s per channel
//   μ_e      = A · FF · (M · film)_k · lux_seconds_per_film         expected photoelectrons
//   e_photo  ~ Poisson(μ_e · (1 + PRNU · g₁(x, y)))                photon shot noise, PRNU
//   e_dark   ~ Poisson(t · max(0, D(T) + DSNU · g₂(x, y)))          dark current, DSNU
//              D(T) = D_ref · 2^((T − T_ref) / T_double)
//   e        = min(e_photo + e_dark, full well)                    saturation
//   DN       = clamp(round(black + K_ISO · (e + σ_read · g₃)), 0, white)
//   white    = min(2^bits − 1, round(black + K_ISO · full well))
//              K_ISO = gain_dn_per_e · ISO / base_ISO
// with g₁, g₂ standard normal per pixel from the sensor's seed (fixed pattern: the same every
// frame) and the Poisson draws and g₃ from the frame's seed. Every random number is a pure
// function of (seed, pixel, draw), so the result does not depend on threads, tiles or ranks.
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/film/image.h"
#include "obscura/sensor/sensor_response.h"
#include "obscura/sensor/sensor_spec.h"

namespace obscura {

// The exposure the film was rendered with, as plain numbers (render/sensor_exposure.h takes
// them from a camera).
struct SensorExposure {
  double exposure_time_s = 1.0 / 60;  // how long the photosites integrate (dark current too)
  double iso = 100;                   // the analog gain, relative to the sensor's base ISO
  // Focal-plane exposure in lux·s that a film value of 1 (white) stands for: q·t / (N²·scale),
  // q = 0.65 as in the physical exposure's ISO 12232 calibration.
  double lux_seconds_per_film = 0.65 / 64 / 60;
};

struct RawCapture {
  int width = 0, height = 0;
  CfaPattern cfa = CfaPattern::kRggb;
  std::vector<uint16_t> raw;      // DN, row-major, one per pixel
  double black_level = 0;         // DN
  double white_level = 0;         // DN a saturated photosite reads (≤ 2^bits − 1)
  double gain_dn_per_e = 1;       // K at the capture's ISO
  double electrons_per_film = 0;  // mean electrons in the green channel per film unit of white
  SensorResponse response;
  // Ground truth: focal-plane irradiance (lux, RGB as the film's channels: the film times
  // lux_seconds_per_film / t), the expected photoelectrons per pixel under its CFA colour
  // without any noise, PRNU, dark signal or clipping.
  Image irradiance_lux;
  Image electrons;
};

// Throws obscura::Error (naming the field) for an invalid spec, exposure or film (fewer than
// three channels).
RawCapture capture_raw(const Image& film, const SensorSpec& spec, const SensorExposure& exposure,
                       uint64_t frame_seed);

// The mosaic as a one-channel float image of DN ("raw").
Image raw_image(const RawCapture& capture);

}  // namespace obscura
