#include "obscura/color/color_space.h"

#include <cmath>

#include "obscura/color/color_models.h"
#include "obscura/color/ycbcr.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

ColorSpaceInfo rgb_space(std::string name, const RgbPrimaries& p, TransferFunction f,
                         std::string description, double linear_scale = 1) {
  ColorSpaceInfo s;
  s.name = std::move(name), s.model = ColorModel::kRgb;
  s.primaries = p, s.transfer = f, s.linear_scale = linear_scale;
  s.xyz_d65_from_rgb = xyz_d65_from_rgb(p);
  s.rgb_from_xyz_d65 = s.xyz_d65_from_rgb.inverse();
  s.description = std::move(description);
  return s;
}

ColorSpaceInfo simple(std::string name, ColorModel model, std::string description,
                      Chromaticity white = white::kD65, int components = 3) {
  ColorSpaceInfo s;
  s.name = std::move(name), s.model = model, s.components = components;
  s.white = white, s.description = std::move(description);
  return s;
}

ColorSpaceInfo ycbcr(std::string name, ColorModel model, YcbcrMatrix m, bool limited) {
  ColorSpaceInfo s;
  s.name = name, s.model = model;
  s.ycbcr_matrix = int(m), s.limited_range = limited;
  s.description = model == ColorModel::kYcbcrFloat
                      ? "Y'CbCr (" + ycbcr_matrix_name(m) + ") of encoded sRGB, floats"
                      : "Y'CbCr (" + ycbcr_matrix_name(m) + ") 8-bit codes of encoded sRGB, " +
                            (limited ? "limited (video) range" : "full range");
  return s;
}

std::vector<ColorSpaceInfo> make_spaces() {
  using TF = TransferFunction;
  std::vector<ColorSpaceInfo> s = {
      rgb_space("srgb", primaries::kRec709, TF::kSrgb, "sRGB, encoded (IEC 61966-2-1)"),
      rgb_space("srgb-linear", primaries::kRec709, TF::kLinear, "linear Rec.709/sRGB, D65"),
      rgb_space("display-p3", primaries::kDisplayP3, TF::kSrgb, "Display P3, sRGB curve"),
      rgb_space("display-p3-linear", primaries::kDisplayP3, TF::kLinear, "linear Display P3"),
      rgb_space("rec2020", primaries::kRec2020, TF::kBt709, "BT.2020, BT.2020 OETF"),
      rgb_space("rec2020-linear", primaries::kRec2020, TF::kLinear, "linear BT.2020"),
      rgb_space("rec2020-g24", primaries::kRec2020, TF::kBt1886, "BT.2020, 2.4 power (BT.1886)"),
      rgb_space("rec2100-pq", primaries::kRec2020, TF::kPq,
                "BT.2100 PQ; diffuse white 1 = 203 cd/m2", 203.0 / 10000),
      rgb_space("rec2100-hlg", primaries::kRec2020, TF::kHlg,
                "BT.2100 HLG; scene light 1 = nominal peak"),
      rgb_space("rec709", primaries::kRec709, TF::kBt709, "Rec.709, BT.709 OETF"),
      rgb_space("srgb-gamma22", primaries::kRec709, TF::kGamma22, "Rec.709 primaries, 2.2 power"),
      rgb_space("acescg", primaries::kAcesAp1, TF::kLinear, "ACEScg, linear AP1, ACES white"),
      rgb_space("aces2065-1", primaries::kAcesAp0, TF::kLinear, "ACES2065-1, linear AP0"),
      simple("xyz-d65", ColorModel::kXyz, "CIE 1931 XYZ, D65 white, Y = 1"),
      simple("xyz-d50", ColorModel::kXyz, "CIE XYZ Bradford-adapted to D50", white::kD50),
      simple("xyy-d65", ColorModel::kXyy, "CIE xyY of XYZ-D65"),
      simple("lab-d65", ColorModel::kLab, "CIE L*a*b*, D65 white"),
      simple("lab-d50", ColorModel::kLab, "CIE L*a*b*, D50 white (Bradford)", white::kD50),
      simple("oklab", ColorModel::kOklab, "OKLab, L in 0..1"),
      simple("oklch", ColorModel::kOklch, "OKLCh: L, chroma, hue in degrees"),
      simple("hsv", ColorModel::kHsv, "HSV of encoded sRGB, hue in degrees"),
      simple("hsl", ColorModel::kHsl, "HSL of encoded sRGB, hue in degrees"),
      simple("cmy", ColorModel::kCmy, "CMY of encoded sRGB (C = 1 - R')"),
      simple("cmyk", ColorModel::kCmyk, "CMYK of encoded sRGB (K = 1 - max)", white::kD65, 4),
      simple("lms-bradford", ColorModel::kLmsBradford, "Bradford response of XYZ-D65"),
  };
  for (YcbcrMatrix m : {YcbcrMatrix::kBt601, YcbcrMatrix::kBt709, YcbcrMatrix::kBt2020}) {
    std::string id = ycbcr_matrix_name(m);
    s.push_back(ycbcr("ycbcr-float-" + id, ColorModel::kYcbcrFloat, m, false));
    s.push_back(ycbcr("ycbcr8-" + id + "-full", ColorModel::kYcbcr8, m, false));
    s.push_back(ycbcr("ycbcr8-" + id + "-limited", ColorModel::kYcbcr8, m, true));
  }
  return s;
}

Vec3d to_vec3(const std::vector<double>& v) {
  return {v[0], v[1], v[2]};
}
std::vector<double> to_vector(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}

const Matrix3d& xyz_d65_from_srgb_linear() {
  static const Matrix3d m = xyz_d65_from_rgb(primaries::kRec709);
  return m;
}
const Matrix3d& srgb_linear_from_xyz_d65() {
  static const Matrix3d m = xyz_d65_from_srgb_linear().inverse();
  return m;
}

// Encoded sRGB ↔ XYZ-D65, the hub of the models defined on encoded sRGB (HSV, HSL, CMY, Y′CbCr).
Vec3d xyz_from_encoded_srgb(const Vec3d& rgb) {
  Vec3d linear;
  for (int i = 0; i < 3; ++i) linear[i] = decode(TransferFunction::kSrgb, rgb[i]);
  return xyz_d65_from_srgb_linear() * linear;
}
Vec3d encoded_srgb_from_xyz(const Vec3d& xyz) {
  Vec3d rgb = srgb_linear_from_xyz_d65() * xyz;
  for (double& c : rgb) c = encode(TransferFunction::kSrgb, c);
  return rgb;
}

bool is_d65(Chromaticity w) {
  return w.x == white::kD65.x && w.y == white::kD65.y;
}

}  // namespace

const std::vector<ColorSpaceInfo>& color_spaces() {
  static const std::vector<ColorSpaceInfo> spaces = make_spaces();
  return spaces;
}

std::optional<ColorSpaceInfo> find_color_space(const std::string& name) {
  for (const ColorSpaceInfo& s : color_spaces())
    if (s.name == name) return s;
  return std::nullopt;
}

const ColorSpaceInfo& color_space(const std::string& name) {
  for (const ColorSpaceInfo& s : color_spaces())
    if (s.name == name) return s;
  std::string known;
  for (const ColorSpaceInfo& s : color_spaces()) known += (known.empty() ? "" : ", ") + s.name;
  throw Error("colour space", "unknown space '" + name + "'; expected one of: " + known);
}

Vec3d xyz_d65_from(const ColorSpaceInfo& s, const std::vector<double>& values) {
  if (int(values.size()) != s.components)
    throw Error(s.name, "expected " + std::to_string(s.components) + " values; got " +
                            std::to_string(values.size()));
  for (double v : values)
    if (!std::isfinite(v)) throw Error(s.name, "values must be finite numbers (no NaN or Inf)");
  if (s.model == ColorModel::kCmyk)
    return xyz_from_encoded_srgb(rgb_from_cmyk({values[0], values[1], values[2], values[3]}));
  Vec3d v = to_vec3(values);
  switch (s.model) {
    case ColorModel::kRgb: {
      Vec3d linear;
      for (int i = 0; i < 3; ++i) linear[i] = decode(s.transfer, v[i]) / s.linear_scale;
      return s.xyz_d65_from_rgb * linear;
    }
    case ColorModel::kXyz:
      return is_d65(s.white) ? v : bradford_adaptation(s.white, white::kD65) * v;
    case ColorModel::kXyy:
      return xyz_from_xyy(v);
    case ColorModel::kLab: {
      Vec3d xyz = xyz_from_lab(v, xyz_from_chromaticity(s.white));
      return is_d65(s.white) ? xyz : bradford_adaptation(s.white, white::kD65) * xyz;
    }
    case ColorModel::kOklab:
      return xyz_d65_from_oklab(v);
    case ColorModel::kOklch:
      return xyz_d65_from_oklab(oklab_from_oklch(v));
    case ColorModel::kHsv:
      return xyz_from_encoded_srgb(rgb_from_hsv(v));
    case ColorModel::kHsl:
      return xyz_from_encoded_srgb(rgb_from_hsl(v));
    case ColorModel::kCmy:
      return xyz_from_encoded_srgb(rgb_from_cmy(v));
    case ColorModel::kLmsBradford:
      return bradford_lms_from_xyz().inverse() * v;
    case ColorModel::kYcbcrFloat:
      return xyz_from_encoded_srgb(rgb_from_ycbcr(v, YcbcrMatrix(s.ycbcr_matrix)));
    case ColorModel::kYcbcr8: {
      for (double c : v)
        if (c < 0 || c > 255 || c != std::floor(c))
          throw Error(s.name, "8-bit codes must be integers in 0..255; got " + std::to_string(c));
      YcbcrCodes codes{uint16_t(v[0]), uint16_t(v[1]), uint16_t(v[2])};
      YcbcrRange range = s.limited_range ? YcbcrRange::kLimited : YcbcrRange::kFull;
      return xyz_from_encoded_srgb(
          rgb_from_ycbcr(ycbcr_from_codes(codes, range), YcbcrMatrix(s.ycbcr_matrix)));
    }
    case ColorModel::kCmyk:
      break;
  }
  return v;
}

std::vector<double> from_xyz_d65(const ColorSpaceInfo& s, const Vec3d& xyz) {
  switch (s.model) {
    case ColorModel::kRgb: {
      Vec3d linear = s.rgb_from_xyz_d65 * xyz;
      std::vector<double> out(3);
      for (int i = 0; i < 3; ++i) out[i] = encode(s.transfer, linear[i] * s.linear_scale);
      return out;
    }
    case ColorModel::kXyz:
      return to_vector(is_d65(s.white) ? xyz : bradford_adaptation(white::kD65, s.white) * xyz);
    case ColorModel::kXyy:
      return to_vector(xyy_from_xyz(xyz, white::kD65.x, white::kD65.y));
    case ColorModel::kLab: {
      Vec3d adapted = is_d65(s.white) ? xyz : bradford_adaptation(white::kD65, s.white) * xyz;
      return to_vector(lab_from_xyz(adapted, xyz_from_chromaticity(s.white)));
    }
    case ColorModel::kOklab:
      return to_vector(oklab_from_xyz_d65(xyz));
    case ColorModel::kOklch:
      return to_vector(oklch_from_oklab(oklab_from_xyz_d65(xyz)));
    case ColorModel::kHsv:
      return to_vector(hsv_from_rgb(encoded_srgb_from_xyz(xyz)));
    case ColorModel::kHsl:
      return to_vector(hsl_from_rgb(encoded_srgb_from_xyz(xyz)));
    case ColorModel::kCmy:
      return to_vector(cmy_from_rgb(encoded_srgb_from_xyz(xyz)));
    case ColorModel::kCmyk: {
      auto c = cmyk_from_rgb(encoded_srgb_from_xyz(xyz));
      return {c[0], c[1], c[2], c[3]};
    }
    case ColorModel::kLmsBradford:
      return to_vector(bradford_lms_from_xyz() * xyz);
    case ColorModel::kYcbcrFloat:
      return to_vector(ycbcr_from_rgb(encoded_srgb_from_xyz(xyz), YcbcrMatrix(s.ycbcr_matrix)));
    case ColorModel::kYcbcr8: {
      Vec3d y = ycbcr_from_rgb(encoded_srgb_from_xyz(xyz), YcbcrMatrix(s.ycbcr_matrix));
      YcbcrCodes q = ycbcr_codes(y, s.limited_range ? YcbcrRange::kLimited : YcbcrRange::kFull);
      return {double(q.y), double(q.cb), double(q.cr)};
    }
  }
  return to_vector(xyz);
}

std::vector<double> convert_color(const std::string& from, const std::string& to,
                                  const std::vector<double>& values) {
  const ColorSpaceInfo& source = color_space(from);
  const ColorSpaceInfo& target = color_space(to);
  return from_xyz_d65(target, xyz_d65_from(source, values));
}

Matrix3d rgb_to_rgb_matrix(const RgbPrimaries& from, const RgbPrimaries& to) {
  return xyz_d65_from_rgb(to).inverse() * xyz_d65_from_rgb(from);
}

bool in_gamut(const RgbPrimaries& space, const Vec3d& xyz_d65, double tolerance,
              bool allow_above_one) {
  Vec3d rgb = xyz_d65_from_rgb(space).inverse() * xyz_d65;
  for (double c : rgb)
    if (c < -tolerance || (!allow_above_one && c > 1 + tolerance)) return false;
  return true;
}

}  // namespace obscura
