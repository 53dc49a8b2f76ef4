// The raw sensor against independent references: photon counts from the definition of the lux,
// the Poisson distribution's own moments and probabilities, saturation and the ADC's range, and
// the same bytes for any number of threads.
#include "obscura/sensor/sensor_capture.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "obscura/color/cie_tables.h"
#include "obscura/math/error.h"
#include "obscura/sensor/isp.h"
#include "obscura/sensor/sensor_noise.h"
#include "sensor_test_scenes.h"

namespace obscura {
namespace {

Image uniform_film(int w, int h, Rgb v) {
  Image film(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) film.set_rgb(x, y, v);
  return film;
}

// A sensor whose only noise is the photon shot noise, one DN per electron.
SensorSpec shot_noise_only() {
  SensorSpec s;
  s.cfa = CfaPattern::kMonochrome;
  s.read_noise_e = 0;
  s.dark_current_e_s = 0;
  s.dsnu_e_s = 0;
  s.prnu = 0;
  s.gain_dn_per_e = 1;
  s.black_level_dn = 100;
  s.adc_bits = 16;
  s.full_well_e = 60000;
  return s;
}

TEST(SensorCapture, PhotonsPerLuxSecondAt555nm) {
  // 1 lux of 555 nm light is 1/683 W/m² (the candela's definition, ȳ(555 nm) = 1); a photon
  // carries hc/λ = 3.5792e-19 J, so 1 lux·s brings 4.0907e15 photons per m².
  std::array<double, 471> line{};
  line[555 - 360] = 1;
  const double hand = (1 / 683.0) / (6.62607015e-34 * 299792458 / 555e-9);
  const double ybar = cie1931_cmf().at(555 - cie1931_cmf().first_nm, 1);
  EXPECT_NEAR(photons_per_lux_second(line) / (hand / ybar), 1, 1e-12);
  EXPECT_NEAR(hand, 4.0907e15, 0.0001e15);
}

TEST(SensorCapture, ShotNoiseIsPoisson) {
  // Mean and variance of a Poisson count are both μ; P(0) = e^−μ.
  for (double mu : {0.5, 3.0, 40.0, 2500.0}) {
    NoiseStream stream(42, 7);
    const int n = 200000;
    double sum = 0, sum_sq = 0;
    int zeros = 0;
    for (int i = 0; i < n; ++i) {
      const double k = stream.poisson(mu);
      ASSERT_EQ(k, std::floor(k));
      sum += k, sum_sq += k * k;
      zeros += k == 0;
    }
    const double mean = sum / n, variance = sum_sq / n - mean * mean;
    EXPECT_NEAR(mean, mu, 4 * std::sqrt(mu / n)) << mu;
    // The sample variance's standard error is about μ·sqrt(2/n) (plus μ/n for small μ).
    EXPECT_NEAR(variance / mu, 1, 4 * std::sqrt(2.0 / n + 1 / (mu * n))) << mu;
    const double p0 = std::exp(-mu);
    EXPECT_NEAR(zeros / double(n), p0, 4 * std::sqrt(p0 * (1 - p0) / n) + 1e-9) << mu;
  }
}

TEST(SensorCapture, MeanSignalFollowsTheExposure) {
  // Shot noise only, one DN per electron: the mean DN above black is the expected electron
  // count, which doubles with the exposure.
  const SensorSpec spec = shot_noise_only();
  const Image film = uniform_film(128, 128, Rgb(1.f));
  SensorExposure e;
  e.lux_seconds_per_film = 0.01;
  double previous = 0;
  for (int stop = 0; stop < 4; ++stop) {
    const RawCapture c = capture_raw(film, spec, e, 3);
    double mean = 0;
    for (uint16_t v : c.raw) mean += v - spec.black_level_dn;
    mean /= double(c.raw.size());
    const double expected = c.electrons.data[0];
    EXPECT_NEAR(mean, expected, 4 * std::sqrt(expected / double(c.raw.size())));
    if (stop > 0) {
      EXPECT_NEAR(expected / previous, 2, 1e-9);
    }
    previous = expected;
    e.lux_seconds_per_film *= 2;
  }
}

TEST(SensorCapture, SaturatesAtTheFullWellAndTheAdcRange) {
  SensorSpec spec = shot_noise_only();
  spec.full_well_e = 5000;
  const Image film = uniform_film(32, 32, Rgb(100.f));
  SensorExposure e;
  e.lux_seconds_per_film = 1;
  RawCapture c = capture_raw(film, spec, e, 1);
  for (uint16_t v : c.raw) ASSERT_EQ(v, 5100);
  EXPECT_EQ(c.white_level, 5100);
  // A gain that would read past 12 bits: the ADC clips at 4095.
  spec.adc_bits = 12;
  spec.gain_dn_per_e = 2;
  c = capture_raw(film, spec, e, 1);
  for (uint16_t v : c.raw) ASSERT_EQ(v, 4095);
  EXPECT_EQ(c.white_level, 4095);
}

TEST(SensorCapture, IsoMultipliesTheGain) {
  const SensorSpec spec = shot_noise_only();
  SensorExposure e;
  e.iso = 400;
  const RawCapture c = capture_raw(uniform_film(4, 4, Rgb(0.f)), spec, e, 1);
  EXPECT_DOUBLE_EQ(c.gain_dn_per_e, spec.gain_dn_per_e * 4);
}

TEST(SensorCapture, SameBytesForAnyThreadCountAndSeedDecides) {
  SensorSpec spec;  // every noise source on
  const Image film = test::rendered_flat_field(96, 64, 0.5);
  SensorExposure e;
  e.lux_seconds_per_film = 0.02;
  RawCapture one, many;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = capture_raw(film, spec, e, 9);
  }
  many = capture_raw(film, spec, e, 9);
  EXPECT_EQ(one.raw, many.raw);
  EXPECT_NE(capture_raw(film, spec, e, 10).raw, one.raw);  // another frame's temporal noise
}

TEST(SensorCapture, DevelopsBackToTheFilm) {
  // A bright uniform colour, averaged over the frame: the white balance and colour matrix
  // invert the sensor's projection (the noise averages out to well under 1 %).
  SensorSpec spec;
  spec.full_well_e = 60000;
  spec.gain_dn_per_e = 0.25;
  spec.adc_bits = 16;
  const Rgb colour(0.30f, 0.50f, 0.20f);
  const Image film = uniform_film(128, 128, colour);
  SensorExposure e;
  RawCapture probe = capture_raw(film, spec, e, 1);
  e.lux_seconds_per_film *= 20000 / probe.electrons.data[1];  // ~20000 e⁻ in a green pixel
  const RawCapture c = capture_raw(film, spec, e, 1);
  for (DemosaicMethod method : {DemosaicMethod::kBilinear, DemosaicMethod::kMalvar}) {
    const Image developed = develop_raw(c, method);
    double mean[3] = {0, 0, 0};
    for (size_t p = 0; p < size_t(128 * 128); ++p)
      for (int ch = 0; ch < 3; ++ch) mean[ch] += developed.data[3 * p + ch] / (128.0 * 128);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(mean[ch] / colour[ch], 1, 0.01) << ch;
  }
}

TEST(SensorCapture, RefusesWhatItCannotCapture) {
  SensorSpec spec;
  spec.read_noise_e = -1;
  EXPECT_THROW(capture_raw(uniform_film(2, 2, Rgb(1.f)), spec, SensorExposure{}, 0), Error);
  SensorExposure e;
  e.exposure_time_s = 0;
  EXPECT_THROW(capture_raw(uniform_film(2, 2, Rgb(1.f)), SensorSpec{}, e, 0), Error);
  EXPECT_THROW(capture_raw(Image(2, 2, 1), SensorSpec{}, SensorExposure{}, 0), Error);
}

}  // namespace
}  // namespace obscura
