#include "obscura/color/display.h"

#include <cmath>

#include "obscura/math/error.h"

namespace obscura {

namespace {
const std::vector<DisplaySpaceInfo>& displays() {
  static const std::vector<DisplaySpaceInfo> d = {
      {DisplaySpace::kSrgb, "srgb", "srgb", primaries::kRec709, TransferFunction::kSrgb, 1.0},
      {DisplaySpace::kDisplayP3, "display-p3", "display-p3", primaries::kDisplayP3,
       TransferFunction::kSrgb, 1.0},
      {DisplaySpace::kRec2020Pq, "rec2020-pq", "rec2100-pq", primaries::kRec2020,
       TransferFunction::kPq, 203.0 / 10000},
      {DisplaySpace::kRec2020Hlg, "rec2020-hlg", "rec2100-hlg", primaries::kRec2020,
       TransferFunction::kHlg, decode(TransferFunction::kHlg, 0.75)},
  };
  return d;
}
}  // namespace

const DisplaySpaceInfo& display_space_info(DisplaySpace id) {
  for (const DisplaySpaceInfo& d : displays())
    if (d.id == id) return d;
  return displays().front();
}

std::vector<std::string> display_space_names() {
  std::vector<std::string> names;
  for (const DisplaySpaceInfo& d : displays()) names.push_back(d.name);
  return names;
}

DisplaySpace parse_display_space(const std::string& name) {
  for (const DisplaySpaceInfo& d : displays())
    if (d.name == name) return d.id;
  throw Error("display", "unknown display '" + name +
                             "'; expected srgb, display-p3, rec2020-pq or rec2020-hlg");
}

void validate(const DisplaySettings& s) {
  check_quantize_bits(s.bits);
  if (!std::isfinite(s.exposure_ev) || std::abs(s.exposure_ev) > 64)
    throw Error("exposure",
                "expected a finite EV within ±64; got " + std::to_string(s.exposure_ev));
  if (!(s.tonemap.reinhard_white > 0) || !std::isfinite(s.tonemap.reinhard_white))
    throw Error("tonemap", "the Reinhard white point must be positive");
}

}  // namespace obscura
