#include "obscura/sensor/sensor_spec.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "obscura/math/number_list.h"
#include "obscura/math/number_text.h"
#include "obscura/math/request_error.h"

namespace obscura {

namespace {

[[noreturn]] void fail(std::string_view field, const std::string& message) {
  throw RequestError("sensor." + std::string(field), message);
}

void check_finite(std::string_view field, double v) {
  if (!std::isfinite(v)) fail(field, "must be a finite number; got " + number_text(v));
}

void check_positive(std::string_view field, double v) {
  check_finite(field, v);
  if (!(v > 0)) fail(field, "must be positive; got " + number_text(v));
}

void check_not_negative(std::string_view field, double v) {
  check_finite(field, v);
  if (v < 0) fail(field, "must not be negative; got " + number_text(v));
}

void check_band(const std::string& name, const QeBand& band) {
  check_finite(name, band.peak);
  if (!(band.peak > 0 && band.peak <= 1))
    fail(name, "a quantum efficiency is a probability in (0, 1]; got " + number_text(band.peak));
  check_finite(name + "_nm", band.center_nm);
  if (band.center_nm < 300 || band.center_nm > 1100)
    fail(name + "_nm",
         "expected a wavelength in [300, 1100] nm; got " + number_text(band.center_nm));
  check_positive(name + "_width_nm", band.width_nm);
}

// The numeric fields by name: where each lives in the spec.
using Setter = std::function<void(SensorSpec&, double)>;
const std::vector<std::pair<std::string, Setter>>& numeric_fields() {
  static const std::vector<std::pair<std::string, Setter>> fields = [] {
    std::vector<std::pair<std::string, Setter>> f;
    auto add = [&](std::string name, double SensorSpec::*member) {
      f.emplace_back(std::move(name), [member](SensorSpec& s, double v) { s.*member = v; });
    };
    add("pixel_pitch_um", &SensorSpec::pixel_pitch_um);
    add("fill_factor", &SensorSpec::fill_factor);
    add("full_well_e", &SensorSpec::full_well_e);
    add("read_noise_e", &SensorSpec::read_noise_e);
    add("dark_current_e_s", &SensorSpec::dark_current_e_s);
    add("temperature_c", &SensorSpec::temperature_c);
    add("dark_reference_c", &SensorSpec::dark_reference_c);
    add("dark_doubling_c", &SensorSpec::dark_doubling_c);
    add("prnu", &SensorSpec::prnu);
    add("dsnu_e_s", &SensorSpec::dsnu_e_s);
    add("gain_dn_per_e", &SensorSpec::gain_dn_per_e);
    add("base_iso", &SensorSpec::base_iso);
    add("black_level_dn", &SensorSpec::black_level_dn);
    // Integers arrive as numbers: a fraction is refused rather than truncated.
    f.emplace_back("adc_bits", [](SensorSpec& s, double v) {
      if (!(std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e6))
        fail("adc_bits", "expected a whole number of bits; got " + number_text(v));
      s.adc_bits = int(v);
    });
    f.emplace_back("seed", [](SensorSpec& s, double v) {
      if (!(v >= 0 && v < 0x1p64 && v == std::floor(v)))
        fail("seed", "expected a whole number in [0, 2^64); got " + number_text(v));
      s.seed = uint64_t(v);
    });
    const char* colours[] = {"red", "green", "blue", "mono"};
    for (int c = 0; c < 4; ++c) {
      auto band = [c](SensorSpec& s) -> QeBand& { return c < 3 ? s.qe[size_t(c)] : s.mono_qe; };
      std::string base = std::string("qe_") + colours[c];
      f.emplace_back(base, [band](SensorSpec& s, double v) { band(s).peak = v; });
      f.emplace_back(base + "_nm", [band](SensorSpec& s, double v) { band(s).center_nm = v; });
      f.emplace_back(base + "_width_nm", [band](SensorSpec& s, double v) { band(s).width_nm = v; });
    }
    return f;
  }();
  return fields;
}

}  // namespace

int cfa_color(CfaPattern pattern, int x, int y) {
  // Colours of the 2 × 2 tile in reading order.
  static constexpr int kTiles[4][4] = {{0, 1, 1, 2}, {2, 1, 1, 0}, {1, 0, 2, 1}, {1, 2, 0, 1}};
  if (pattern == CfaPattern::kMonochrome) return 1;
  return kTiles[int(pattern)][(y & 1) * 2 + (x & 1)];
}

std::string_view cfa_pattern_name(CfaPattern pattern) {
  switch (pattern) {
    case CfaPattern::kRggb:
      return "RGGB";
    case CfaPattern::kBggr:
      return "BGGR";
    case CfaPattern::kGrbg:
      return "GRBG";
    case CfaPattern::kGbrg:
      return "GBRG";
    case CfaPattern::kMonochrome:
      return "mono";
  }
  return "RGGB";
}

CfaPattern parse_cfa_pattern(std::string_view text, const std::string& field) {
  std::string upper(text);
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return char(std::toupper(c)); });
  if (upper == "RGGB") return CfaPattern::kRggb;
  if (upper == "BGGR") return CfaPattern::kBggr;
  if (upper == "GRBG") return CfaPattern::kGrbg;
  if (upper == "GBRG") return CfaPattern::kGbrg;
  if (upper == "MONO" || upper == "MONOCHROME") return CfaPattern::kMonochrome;
  throw RequestError(field,
                     "expected RGGB, BGGR, GRBG, GBRG or mono; got '" + std::string(text) + "'");
}

void SensorSpec::validate() const {
  check_positive("pixel_pitch_um", pixel_pitch_um);
  check_finite("fill_factor", fill_factor);
  if (!(fill_factor > 0 && fill_factor <= 1))
    fail("fill_factor", "expected a share in (0, 1]; got " + number_text(fill_factor));
  const char* names[] = {"qe_red", "qe_green", "qe_blue"};
  for (size_t c = 0; c < 3; ++c) check_band(names[c], qe[c]);
  check_band("qe_mono", mono_qe);
  check_positive("full_well_e", full_well_e);
  check_not_negative("read_noise_e", read_noise_e);
  check_not_negative("dark_current_e_s", dark_current_e_s);
  check_finite("temperature_c", temperature_c);
  if (temperature_c < -273.15)
    fail("temperature_c", "is below absolute zero: " + number_text(temperature_c));
  check_finite("dark_reference_c", dark_reference_c);
  check_positive("dark_doubling_c", dark_doubling_c);
  check_not_negative("prnu", prnu);
  if (prnu > 0.5) fail("prnu", "expected a gain spread σ of at most 0.5; got " + number_text(prnu));
  check_not_negative("dsnu_e_s", dsnu_e_s);
  check_positive("gain_dn_per_e", gain_dn_per_e);
  check_positive("base_iso", base_iso);
  if (adc_bits < 1 || adc_bits > 16)
    fail("adc_bits", "expected 1 to 16 bits (the raw mosaic is stored in 16 bits); got " +
                         std::to_string(adc_bits));
  check_not_negative("black_level_dn", black_level_dn);
  const double largest = std::exp2(adc_bits) - 1;
  if (black_level_dn >= largest)
    fail("black_level_dn", "must lie below the ADC's largest value " + number_text(largest) +
                               "; got " + number_text(black_level_dn));
}

void set_sensor_number(SensorSpec& spec, std::string_view name, double value) {
  for (const auto& [field, set] : numeric_fields())
    if (field == name) return set(spec, value);
  if (name == "cfa") fail(name, "expects a pattern name (RGGB, BGGR, GRBG, GBRG, mono)");
  fail(name, "unknown sensor field; expected one of " + sensor_field_names());
}

void set_sensor_field(SensorSpec& spec, std::string_view name, std::string_view value) {
  if (name == "cfa") {
    spec.cfa = parse_cfa_pattern(value);
    return;
  }
  for (const auto& [field, set] : numeric_fields())
    if (field == name) return set(spec, parse_number(std::string(value), "sensor." + field));
  fail(name, "unknown sensor field; expected one of " + sensor_field_names());
}

std::string sensor_field_names() {
  std::string names = "cfa";
  for (const auto& field : numeric_fields()) names += ", " + field.first;
  return names;
}

void apply_sensor_fields(SensorSpec& spec, std::string_view text) {
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(',', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view item = text.substr(start, end - start);
    size_t equals = item.find('=');
    if (equals == std::string_view::npos || equals == 0)
      throw RequestError("sensor", "expected KEY=VALUE pairs separated by commas; got '" +
                                       std::string(item) + "'");
    set_sensor_field(spec, item.substr(0, equals), item.substr(equals + 1));
    start = end + 1;
  }
  spec.validate();
}

}  // namespace obscura
