#include "obscura/color/color_models.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace obscura {

Vec3d xyy_from_xyz(const Vec3d& xyz, double black_x, double black_y) {
  double sum = xyz[0] + xyz[1] + xyz[2];
  if (sum == 0) return {black_x, black_y, 0};
  return {xyz[0] / sum, xyz[1] / sum, xyz[1]};
}

Vec3d xyz_from_xyy(const Vec3d& xyy) {
  double x = xyy[0], y = xyy[1], Y = xyy[2];
  if (y == 0) return {0, 0, 0};
  return {x * Y / y, Y, (1 - x - y) * Y / y};
}

namespace {
constexpr double kLabEpsilon = 216.0 / 24389;  // (6/29)³
constexpr double kLabKappa = 24389.0 / 27;     // (29/3)³
}  // namespace

Vec3d lab_from_xyz(const Vec3d& xyz, const Vec3d& white) {
  auto f = [](double t) { return t > kLabEpsilon ? std::cbrt(t) : (kLabKappa * t + 16) / 116; };
  double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

Vec3d xyz_from_lab(const Vec3d& lab, const Vec3d& white) {
  double fy = (lab[0] + 16) / 116;
  double fx = fy + lab[1] / 500;
  double fz = fy - lab[2] / 200;
  auto finv = [](double f) {
    double f3 = f * f * f;
    return f3 > kLabEpsilon ? f3 : (116 * f - 16) / kLabKappa;
  };
  double yr = lab[0] > kLabKappa * kLabEpsilon ? fy * fy * fy : lab[0] / kLabKappa;
  return {finv(fx) * white[0], yr * white[1], finv(fz) * white[2]};
}

namespace {

const Matrix3d& lms_from_xyz_oklab() {
  static const Matrix3d m{{{{0.8190224379967030, 0.3619062600528904, -0.1288737815209879},
                            {0.0329836539323885, 0.9292868615863434, 0.0361446663506424},
                            {0.0481771893596242, 0.2642395317527308, 0.6335478284694309}}}};
  return m;
}
const Matrix3d& oklab_from_lms() {
  static const Matrix3d m{{{{0.2104542683093140, 0.7936177747023054, -0.0040720430116193},
                            {1.9779985324311684, -2.4285922420485799, 0.4505937096174110},
                            {0.0259040424655478, 0.7827717124575296, -0.8086757549230774}}}};
  return m;
}

}  // namespace

Vec3d oklab_from_xyz_d65(const Vec3d& xyz) {
  Vec3d lms = lms_from_xyz_oklab() * xyz;
  for (double& c : lms) c = std::cbrt(c);
  return oklab_from_lms() * lms;
}

Vec3d xyz_d65_from_oklab(const Vec3d& lab) {
  static const Matrix3d xyz_from_lms = lms_from_xyz_oklab().inverse();
  static const Matrix3d lms_from_oklab = oklab_from_lms().inverse();
  Vec3d lms = lms_from_oklab * lab;
  for (double& c : lms) c = c * c * c;
  return xyz_from_lms * lms;
}

Vec3d oklch_from_oklab(const Vec3d& lab) {
  double hue = std::atan2(lab[2], lab[1]) * 180 / std::numbers::pi;
  if (hue < 0) hue += 360;
  return {lab[0], std::hypot(lab[1], lab[2]), hue};
}

Vec3d oklab_from_oklch(const Vec3d& lch) {
  double h = lch[2] * std::numbers::pi / 180;
  return {lch[0], lch[1] * std::cos(h), lch[1] * std::sin(h)};
}

namespace {

// A colour whose channels differ by less than this (relative to its size) is a grey: conversions
// through XYZ leave (1, 1, 1) as 1 ± 2e-16 per channel, and that noise has no hue or saturation.
bool achromatic(double max, double min) {
  double scale = std::max({1.0, std::abs(max), std::abs(min)});
  return max - min <= 1e-9 * scale;
}

// The hue angle shared by HSV and HSL: which sextant the largest channel puts the colour in
// (0 for a grey, whose hue CSS Color 4 calls "powerless").
double hue_degrees(const Vec3d& c, double max, double chroma) {
  if (chroma == 0) return 0;
  double h;
  if (max == c[0])
    h = (c[1] - c[2]) / chroma + (c[1] < c[2] ? 6 : 0);
  else if (max == c[1])
    h = (c[2] - c[0]) / chroma + 2;
  else
    h = (c[0] - c[1]) / chroma + 4;
  return h * 60;
}

// R'G'B' from hue, chroma and the amount m added to every channel.
Vec3d rgb_from_hue_chroma(double hue, double chroma, double m) {
  double h = std::fmod(std::fmod(hue, 360) + 360, 360) / 60;
  double x = chroma * (1 - std::abs(std::fmod(h, 2) - 1));
  Vec3d c;
  switch (int(h)) {
    case 0:
      c = {chroma, x, 0};
      break;
    case 1:
      c = {x, chroma, 0};
      break;
    case 2:
      c = {0, chroma, x};
      break;
    case 3:
      c = {0, x, chroma};
      break;
    case 4:
      c = {x, 0, chroma};
      break;
    default:
      c = {chroma, 0, x};
      break;
  }
  return {c[0] + m, c[1] + m, c[2] + m};
}

}  // namespace

Vec3d hsv_from_rgb(const Vec3d& c) {
  double max = std::max({c[0], c[1], c[2]}), min = std::min({c[0], c[1], c[2]});
  if (achromatic(max, min)) return {0, 0, max};
  double chroma = max - min;
  // At or below black (value ≤ 0) there is no saturation to speak of.
  return {hue_degrees(c, max, chroma), max <= 0 ? 0 : chroma / max, max};
}

Vec3d rgb_from_hsv(const Vec3d& hsv) {
  double chroma = hsv[2] * hsv[1];
  return rgb_from_hue_chroma(hsv[0], chroma, hsv[2] - chroma);
}

// CSS Color 4, §7.1 (rgbToHsl): S = (max − L) / min(L, 1 − L), 0 at L = 0 or 1; a negative S
// (a colour outside the sRGB cube) becomes positive with the hue turned half way round.
Vec3d hsl_from_rgb(const Vec3d& c) {
  double max = std::max({c[0], c[1], c[2]}), min = std::min({c[0], c[1], c[2]});
  double lightness = (max + min) / 2;
  if (achromatic(max, min)) return {0, 0, lightness};
  double chroma = max - min;
  double hue = hue_degrees(c, max, chroma);
  // Lightness at white or black (within rounding) leaves no room for saturation: S would be a
  // quotient of noise.
  double room = std::min(lightness, 1 - lightness);
  if (std::abs(room) <= 1e-9) return {hue, 0, lightness};
  double saturation = (max - lightness) / room;
  if (saturation < 0) {
    saturation = -saturation;
    hue = hue >= 180 ? hue - 180 : hue + 180;
  }
  return {hue, saturation, lightness};
}

Vec3d rgb_from_hsl(const Vec3d& hsl) {
  double chroma = (1 - std::abs(2 * hsl[2] - 1)) * hsl[1];
  return rgb_from_hue_chroma(hsl[0], chroma, hsl[2] - chroma / 2);
}

Vec3d cmy_from_rgb(const Vec3d& rgb) {
  return {1 - rgb[0], 1 - rgb[1], 1 - rgb[2]};
}
Vec3d rgb_from_cmy(const Vec3d& cmy) {
  return {1 - cmy[0], 1 - cmy[1], 1 - cmy[2]};
}

std::array<double, 4> cmyk_from_rgb(const Vec3d& rgb) {
  double k = 1 - std::max({rgb[0], rgb[1], rgb[2]});
  if (k >= 1) return {0, 0, 0, 1};
  double s = 1 / (1 - k);
  return {(1 - rgb[0] - k) * s, (1 - rgb[1] - k) * s, (1 - rgb[2] - k) * s, k};
}

Vec3d rgb_from_cmyk(const std::array<double, 4>& cmyk) {
  double w = 1 - cmyk[3];
  return {(1 - cmyk[0]) * w, (1 - cmyk[1]) * w, (1 - cmyk[2]) * w};
}

}  // namespace obscura
