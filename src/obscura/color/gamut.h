// Gamut handling: what to do with a colour the target display cannot show.
//
// Clip clamps each channel to [0, 1]: cheap, but it shifts hue (a too-saturated orange turns
// yellow). Compress follows CSS Color 4's gamut mapping: keep OKLCh lightness and hue and reduce
// chroma (by bisection) until clipping the result changes it by less than a just-noticeable
// difference (ΔE_OK 0.02).
#pragma once

#include <string>

#include "obscura/color/color_space.h"

namespace obscura {

enum class GamutMapping { kClip, kCompress };
std::string gamut_mapping_name(GamutMapping g);             // "clip", "compress"
GamutMapping parse_gamut_mapping(const std::string& name);  // throws obscura::Error

// Encoded values of an RGB space `space` (kRgb) in, encoded values inside [0, 1]³ out.
Vec3d gamut_clip(const Vec3d& encoded);
Vec3d gamut_map_css(const Vec3d& encoded, const ColorSpaceInfo& space);

// Whether encoded values of an RGB space lie in [−tolerance, 1 + tolerance]³.
bool encoded_in_gamut(const Vec3d& encoded, double tolerance = 1e-6);

}  // namespace obscura
