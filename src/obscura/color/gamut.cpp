#include "obscura/color/gamut.h"

#include <algorithm>
#include <cmath>

#include "obscura/color/color_models.h"
#include "obscura/math/error.h"

namespace obscura {

std::string gamut_mapping_name(GamutMapping g) {
  return g == GamutMapping::kClip ? "clip" : "compress";
}

GamutMapping parse_gamut_mapping(const std::string& name) {
  if (name == "clip") return GamutMapping::kClip;
  if (name == "compress") return GamutMapping::kCompress;
  throw Error("gamut", "unknown gamut mapping '" + name + "'; expected clip or compress");
}

Vec3d gamut_clip(const Vec3d& e) {
  return {std::clamp(e[0], 0.0, 1.0), std::clamp(e[1], 0.0, 1.0), std::clamp(e[2], 0.0, 1.0)};
}

bool encoded_in_gamut(const Vec3d& e, double tolerance) {
  for (double c : e)
    if (!(c >= -tolerance && c <= 1 + tolerance)) return false;
  return true;
}

Vec3d gamut_map_css(const Vec3d& encoded, const ColorSpaceInfo& space) {
  if (space.model != ColorModel::kRgb) throw Error(space.name, "gamut mapping needs an RGB space");
  constexpr double kJnd = 0.02, kEpsilon = 1e-4;
  auto to_oklab = [&](const Vec3d& e) {
    return oklab_from_xyz_d65(xyz_d65_from(space, {e[0], e[1], e[2]}));
  };
  auto from_oklch = [&](const Vec3d& lch) {
    std::vector<double> e = from_xyz_d65(space, xyz_d65_from_oklab(oklab_from_oklch(lch)));
    return Vec3d{e[0], e[1], e[2]};
  };
  auto delta_e = [](const Vec3d& a, const Vec3d& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  };

  Vec3d origin = oklch_from_oklab(to_oklab(encoded));
  if (origin[0] >= 1) return {1, 1, 1};
  if (origin[0] <= 0) return {0, 0, 0};
  if (encoded_in_gamut(encoded)) return encoded;

  Vec3d current = encoded;
  Vec3d clipped = gamut_clip(current);
  if (delta_e(to_oklab(clipped), to_oklab(current)) < kJnd) return clipped;

  double low = 0, high = origin[1];
  bool low_in_gamut = true;
  while (high - low > kEpsilon) {
    double chroma = (low + high) / 2;
    current = from_oklch({origin[0], chroma, origin[2]});
    if (low_in_gamut && encoded_in_gamut(current)) {
      low = chroma;
      continue;
    }
    clipped = gamut_clip(current);
    double e = delta_e(to_oklab(clipped), to_oklab(current));
    if (e < kJnd) {
      if (kJnd - e < kEpsilon) break;
      low_in_gamut = false;
      low = chroma;
    } else {
      high = chroma;
    }
  }
  return clipped;
}

}  // namespace obscura
