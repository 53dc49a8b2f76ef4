// Displays Obscura can encode for, and the settings that turn linear light into their signal.
#pragma once

#include <string>
#include <vector>

#include "obscura/color/gamut.h"
#include "obscura/color/primaries.h"
#include "obscura/color/quantize.h"
#include "obscura/color/tonemap.h"
#include "obscura/color/transfer.h"

namespace obscura {

enum class DisplaySpace {
  kSrgb,        // Rec.709 primaries, sRGB curve: the web, most monitors
  kDisplayP3,   // P3 primaries, D65, sRGB curve: Apple displays, wide-gamut phones
  kRec2020Pq,   // BT.2100 PQ: Rec.2020 primaries, ST 2084, diffuse white at 203 cd/m²
  kRec2020Hlg,  // BT.2100 HLG: Rec.2020 primaries, the HLG OETF, diffuse white at 75 % signal
};

struct DisplaySpaceInfo {
  DisplaySpace id;
  std::string name;         // command-line name: "srgb", "display-p3", "rec2020-pq", "rec2020-hlg"
  std::string color_space;  // the id in color_space.h: "srgb", "display-p3", "rec2100-pq", …
  RgbPrimaries primaries;
  TransferFunction transfer;
  // encoded = transfer(linear · scale). PQ: 203/10000 (diffuse white at 203 cd/m²); HLG: the
  // scene light E = 0.2650 whose OETF is 0.75, where ITU-R BT.2408 puts diffuse white.
  double linear_scale;
};

const DisplaySpaceInfo& display_space_info(DisplaySpace d);
DisplaySpace parse_display_space(const std::string& name);  // throws obscura::Error
std::vector<std::string> display_space_names();

// From film (linear Rec.709, scene-referred) to display codes.
struct DisplaySettings {
  float exposure_ev = 0;    // scale by 2^EV before tone mapping
  ToneMapSettings tonemap;  // default: clamp
  DisplaySpace display = DisplaySpace::kSrgb;
  GamutMapping gamut = GamutMapping::kClip;
  int bits = 8;  // 1…16 per channel
  Dither dither = Dither::kNone;
};

// Throws obscura::Error for settings out of range (bits, a non-finite exposure, white ≤ 0).
void validate(const DisplaySettings& s);

}  // namespace obscura
