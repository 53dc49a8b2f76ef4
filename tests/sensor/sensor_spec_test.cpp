// The sensor's description: the CFA layouts as the DNG specification and LibRaw name them, and
// bad parameters refused with the field named.
#include "obscura/sensor/sensor_spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "obscura/math/request_error.h"
#include "test_files.h"

namespace obscura {
namespace {

TEST(SensorSpec, BayerTilesReadInReadingOrder) {
  // The name lists the 2 × 2 tile's colours left to right, top to bottom (DNG's CFAPattern).
  const struct {
    CfaPattern pattern;
    const char* colours;
  } cases[] = {{CfaPattern::kRggb, "RGGB"},
               {CfaPattern::kBggr, "BGGR"},
               {CfaPattern::kGrbg, "GRBG"},
               {CfaPattern::kGbrg, "GBRG"}};
  for (const auto& c : cases) {
    std::string read;
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) read += "RGB"[cfa_color(c.pattern, x, y)];
    EXPECT_EQ(read, c.colours);
    EXPECT_EQ(cfa_pattern_name(c.pattern), c.colours);
    EXPECT_EQ(parse_cfa_pattern(c.colours), c.pattern);
    // The tile repeats every two pixels in both directions.
    EXPECT_EQ(cfa_color(c.pattern, 7, 5), cfa_color(c.pattern, 1, 1));
  }
  EXPECT_EQ(parse_cfa_pattern("rggb"), CfaPattern::kRggb);
  EXPECT_EQ(parse_cfa_pattern("mono"), CfaPattern::kMonochrome);
  EXPECT_NE(test::error_of([] { parse_cfa_pattern("RGBW"); }).find("sensor.cfa"),
            std::string::npos);
}

TEST(SensorSpec, DefaultsAreValid) {
  EXPECT_NO_THROW(SensorSpec{}.validate());
}

TEST(SensorSpec, BadValuesNameTheirField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const struct {
    const char* field;
    double value;
  } cases[] = {{"read_noise_e", -1},
               {"full_well_e", 0},
               {"qe_red", 1.2},
               {"qe_mono", 0},
               {"adc_bits", 0},
               {"adc_bits", 64},
               {"prnu", nan},
               {"dark_current_e_s", -2},
               {"gain_dn_per_e", 0},
               {"pixel_pitch_um", nan},
               {"fill_factor", 1.5},
               {"dsnu_e_s", -0.1},
               {"black_level_dn", 20000},
               {"qe_green_width_nm", 0},
               {"adc_bits", 12.5}};
  for (const auto& c : cases) {
    SensorSpec spec;
    const std::string message = test::error_of([&] {
      set_sensor_number(spec, c.field, c.value);
      spec.validate();
    });
    EXPECT_EQ(message.rfind(std::string("sensor.") + c.field + ": ", 0), 0u)
        << c.field << " = " << c.value << ": " << message;
  }
}

TEST(SensorSpec, FieldsParseFromText) {
  SensorSpec spec;
  apply_sensor_fields(spec, "cfa=gbrg,full_well_e=51000,read_noise_e=1.6,adc_bits=12,seed=7");
  EXPECT_EQ(spec.cfa, CfaPattern::kGbrg);
  EXPECT_EQ(spec.full_well_e, 51000);
  EXPECT_EQ(spec.read_noise_e, 1.6);
  EXPECT_EQ(spec.adc_bits, 12);
  EXPECT_EQ(spec.seed, 7u);
  // An unknown name lists the known ones; a non-number names its field; a bad value is an
  // error of the request (exit status 2, Python's ValueError).
  EXPECT_NE(test::error_of([&] {
              apply_sensor_fields(spec, "full_wel=3");
            }).find("unknown sensor field; expected one of cfa, pixel_pitch_um"),
            std::string::npos);
  EXPECT_NE(test::error_of([&] {
              apply_sensor_fields(spec, "read_noise_e=nan");
            }).find("sensor.read_noise_e"),
            std::string::npos);
  EXPECT_THROW(apply_sensor_fields(spec, "adc_bits=0"), RequestError);
  EXPECT_THROW(apply_sensor_fields(spec, "full_well_e"), RequestError);
}

}  // namespace
}  // namespace obscura
