// Tone mapping: from scene-referred linear light (any value ≥ 0) to display-referred [0, 1].
//
// Operators work per channel on linear RGB, after exposure. "none" passes values through (an HDR
// display keeps what is above 1; an SDR encoder then clips); "clamp" clips at 1 here.
#pragma once

#include <string>

#include "obscura/color/rgb.h"

namespace obscura {

enum class ToneMap {
  kNone,      // identity
  kClamp,     // min(x, 1)
  kReinhard,  // extended Reinhard x(1 + x/w²)/(1 + x): maps white point w to exactly 1
  kAces,      // Narkowicz's 2015 fit of the ACES RRT + sRGB ODT filmic curve
  kHable,     // Hable's "Uncharted 2" filmic curve, white at 11.2
};

std::string tone_map_name(ToneMap t);             // "none", "clamp", "reinhard", "aces", "hable"
ToneMap parse_tone_map(const std::string& name);  // throws obscura::Error listing the names

struct ToneMapSettings {
  ToneMap op = ToneMap::kClamp;
  float reinhard_white = 4;  // linear value that maps to 1 (> 0)
};

float tone_map(float x, const ToneMapSettings& s);
Rgb tone_map(Rgb c, const ToneMapSettings& s);

}  // namespace obscura
