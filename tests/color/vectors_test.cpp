// Every record of tests/data/color/vectors-public.json (computed by an independent
// implementation: colorjs.io and the standards' formulas in exact arithmetic), checked at the
// record's own tolerance: |actual − expected| ≤ abs[i] + rel·|expected|, hues compared mod 360.
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "obscura/color/color_space.h"
#include "obscura/color/gamut.h"
#include "obscura/color/quantize.h"
#include "obscura/color/spectral.h"
#include "obscura/color/ycbcr.h"
#include "test_paths.h"

namespace obscura {
namespace {

using nlohmann::json;

const json& vectors() {
  static const json v = [] {
    std::ifstream in(test::data_path("color/vectors-public.json"));
    EXPECT_TRUE(in.good()) << "cannot open vectors-public.json";
    return json::parse(in);
  }();
  return v;
}

bool is_hue(const std::string& space, size_t i) {
  return (space == "hsv" || space == "hsl") && i == 0;
}

// Checks one record's actual values; returns a failure description or "".
std::string check(const json& record, const std::vector<double>& actual) {
  const json& expected = record["expected"];
  const json& tolerance = record["tolerance"];
  std::string out_space = record["output_space"];
  if (actual.size() != expected.size()) return "wrong number of components";
  double rel = tolerance["rel"];
  for (size_t i = 0; i < actual.size(); ++i) {
    if (tolerance["abs"][i].is_null()) continue;
    double e = expected[i], a = actual[i], abs = tolerance["abs"][i];
    double diff = std::abs(a - e);
    if (is_hue(out_space, i)) diff = std::min(std::fmod(diff, 360.0), 360 - std::fmod(diff, 360.0));
    if (!(diff <= abs + rel * std::abs(e)))
      return "component " + std::to_string(i) + ": got " + std::to_string(a) + ", expected " +
             std::to_string(e) + " (|diff| " + std::to_string(diff) + ")";
  }
  return "";
}

int bits_of(const std::string& space) {
  return std::stoi(space.substr(4));
}  // "uintN"

YcbcrMatrix matrix_of(const std::string& space) {
  if (space.find("bt601") != std::string::npos) return YcbcrMatrix::kBt601;
  if (space.find("bt2020") != std::string::npos) return YcbcrMatrix::kBt2020;
  return YcbcrMatrix::kBt709;
}
YcbcrRange range_of(const std::string& space) {
  return space.find("limited") != std::string::npos ? YcbcrRange::kLimited : YcbcrRange::kFull;
}

std::vector<double> evaluate(const json& r) {
  std::string op = r["op"], in = r["input_space"], out = r["output_space"];
  if (op == "convert") return convert_color(in, out, r["input"].get<std::vector<double>>());
  if (op == "gamut-map-css-color-4") {
    std::vector<double> v = r["input"];
    Vec3d m = gamut_map_css(Vec3d{v[0], v[1], v[2]}, color_space(out));
    return {m[0], m[1], m[2]};
  }
  if (op == "quantize") return {double(quantize(r["input"][0].get<double>(), bits_of(out)))};
  if (op == "dequantize") return {dequantize(r["input"][0].get<uint32_t>(), bits_of(in))};
  if (op == "requantize")
    return {double(requantize(r["input"][0].get<uint32_t>(), bits_of(in), bits_of(out)))};
  if (op == "ycbcr-encode") {
    std::vector<double> v = r["input"];
    if (in == "rgb8") {
      Vec3d rgb{v[0] / 255, v[1] / 255, v[2] / 255};
      YcbcrCodes q = ycbcr_codes(ycbcr_from_rgb(rgb, matrix_of(out)), range_of(out));
      return {double(q.y), double(q.cb), double(q.cr)};
    }
    Vec3d y = ycbcr_from_rgb({v[0], v[1], v[2]}, matrix_of(out));
    return {y[0], y[1], y[2]};
  }
  if (op == "ycbcr-decode") {
    std::vector<uint16_t> q = r["input"];
    Vec3d rgb = rgb_from_ycbcr(ycbcr_from_codes({q[0], q[1], q[2]}, range_of(in)), matrix_of(in));
    return {rgb[0], rgb[1], rgb[2]};
  }
  if (op == "spectral") {
    auto xyz_to = [](const Vec3d& xyz, const std::string& space) {
      return from_xyz_d65(color_space(space), xyz);
    };
    if (in == "wavelength-nm") {
      double nm = r["input"][0];
      Vec3d xyz = cmf_xyz(nm);
      if (out == "xyz-cmf-1931") return {xyz[0], xyz[1], xyz[2]};
      if (out == "xy-1931") return {chromaticity_of(xyz).x, chromaticity_of(xyz).y};
      if (out == "srgb-linear") return xyz_to(xyz, out);
      if (out == "lms-stockman-sharpe-2deg") {
        Vec3d lms = cone_lms(nm);
        return {lms[0], lms[1], lms[2]};
      }
    }
    if (in == "blackbody-kelvin") {
      Vec3d xyz = blackbody_xyz(r["input"][0].get<double>());
      if (out == "xy-1931") return {chromaticity_of(xyz).x, chromaticity_of(xyz).y};
      if (out == "srgb-linear") return xyz_to(xyz, out);
    }
    if (in == "wavelength-nm,kelvin")
      return {planck_radiance(r["input"][0].get<double>(), r["input"][1].get<double>())};
    if (in == "illuminant" && r["input"][0] == "D65") {
      if (out == "lms-stockman-sharpe-2deg-sum") {
        Vec3d lms = spectrum_to_lms(d65_spd);
        return {lms[0], lms[1], lms[2]};
      }
      Vec3d xyz = spectrum_to_xyz(d65_spd);
      if (out == "xy-1931") return {chromaticity_of(xyz).x, chromaticity_of(xyz).y};
      if (out == "xyz-1931-Y100") return {xyz[0] * 100 / xyz[1], 100, xyz[2] * 100 / xyz[1]};
    }
  }
  ADD_FAILURE() << "record " << r["id"] << ": operation not handled by the test";
  return {};
}

TEST(ColorVectors, EveryPublicRecordWithinItsTolerance) {
  const json& records = vectors()["records"];
  ASSERT_GT(records.size(), 4000u);
  int checked = 0, failed = 0;
  for (const json& r : records) {
    std::string failure = check(r, evaluate(r));
    ++checked;
    if (!failure.empty() && ++failed <= 20) ADD_FAILURE() << r["id"] << ": " << failure;
  }
  EXPECT_EQ(failed, 0) << "of " << checked << " records";
}

}  // namespace
}  // namespace obscura
