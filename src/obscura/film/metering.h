// Reflected-light metering of a film that holds scene luminance (radiance mode, compensation 0:
// the film's Rec.709 Y is luminance in cd/m²), as a camera's meter reads a scene.
//
// ISO 2720:1974's reflected-light calibration: a meter of calibration constant K = 12.5 reads
// luminance L (cd/m²) at ISO S as the exposure value EV_S with 2^EV_S = N²/t = L·S/K, so
//   EV100 = log₂(L · 100 / 12.5) = log₂(8 L).
// The metering pattern decides which L:
//   average          the mean luminance of the frame;
//   centre-weighted  ¾ the mean of a central disc whose diameter is half the frame's height,
//                    ¼ the mean of the rest (the classic 75/25 split of SLR meters);
//   spot             the mean of a central disc covering 3 % of the frame.
#pragma once

#include <string_view>

#include "obscura/film/image.h"

namespace obscura {

enum class MeteringMode { kAverage, kCenterWeighted, kSpot };

inline constexpr double kIso2720K = 12.5;

// "average", "center-weighted" (or "centre-weighted") or "spot"; throws obscura::RequestError.
MeteringMode parse_metering_mode(std::string_view text);
std::string_view metering_mode_name(MeteringMode mode);

// The luminance the pattern reads (cd/m²) from an RGB film in scene luminance units; NaN and
// negative pixels count as 0. Throws obscura::Error for an image with fewer than 3 channels.
double metered_luminance(const Image& film, MeteringMode mode);

// EV100 = log₂(L · 100 / K), K = 12.5. −∞ for L = 0.
double metered_ev100(double luminance_cd_m2);

}  // namespace obscura
