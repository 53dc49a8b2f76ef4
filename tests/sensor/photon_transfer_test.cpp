// The photon-transfer method of EMVA 1288 (release 4.0, "Linear" section): from pairs of flat
// fields at increasing exposure the test recovers the system gain K (DN/e⁻) as the slope of the
// temporal variance over the mean, the read noise from dark frames, the saturation capacity at
// the variance's peak, and the dark current from dark frames at increasing exposure time — and
// compares each with what the sensor was given. The statistics are EMVA's: means over the frame,
// temporal variance from the difference of two frames (which cancels PRNU and DSNU).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "obscura/sensor/sensor_capture.h"
#include "sensor_test_scenes.h"

namespace obscura {
namespace {

constexpr int kSide = 256;

SensorSpec test_sensor() {
  SensorSpec s;
  s.cfa = CfaPattern::kMonochrome;
  s.full_well_e = 12000;
  s.read_noise_e = 3;
  s.gain_dn_per_e = 0.5;
  s.black_level_dn = 200;
  s.adc_bits = 14;
  s.prnu = 0.005;
  s.dsnu_e_s = 2;
  s.dark_current_e_s = 50;
  s.temperature_c = 25;
  s.dark_reference_c = 25;
  return s;
}

struct PairStats {
  double mean = 0;      // μ_y, DN (of the two frames)
  double variance = 0;  // σ_y², DN²: var(A − B) / 2
};

PairStats pair_stats(const Image& film, const SensorSpec& spec, const SensorExposure& e) {
  const RawCapture a = capture_raw(film, spec, e, 1), b = capture_raw(film, spec, e, 2);
  double sum = 0, diff_sum = 0, diff_sq = 0;
  const double n = double(a.raw.size());
  for (size_t i = 0; i < a.raw.size(); ++i) {
    sum += double(a.raw[i]) + double(b.raw[i]);
    const double d = double(a.raw[i]) - double(b.raw[i]);
    diff_sum += d;
    diff_sq += d * d;
  }
  const double diff_mean = diff_sum / n;
  return {sum / (2 * n), (diff_sq / n - diff_mean * diff_mean) / 2};
}

// Least-squares slope through the points (x, y).
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= double(x.size()), my /= double(y.size());
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i)
    sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
  return sxy / sxx;
}

TEST(PhotonTransfer, RecoversGainReadNoiseAndFullWell) {
  const SensorSpec spec = test_sensor();
  const Image flat = test::rendered_flat_field(kSide, kSide, 1.0);
  const Image dark(kSide, kSide, 3);  // the lens capped
  ASSERT_FLOAT_EQ(flat.at(kSide / 2, kSide / 2, 1), 1.f);

  // A short exposure (1 ms): the dark signal is 0.05 e⁻, far below the read noise.
  SensorExposure e;
  e.exposure_time_s = 1e-3;
  e.iso = 100;
  const PairStats dark_stats = pair_stats(dark, spec, e);

  // The flat field's electrons per lux·s, from one noiseless capture: the exposure for a
  // given mean signal.
  e.lux_seconds_per_film = 1;
  const double electrons_per_lux_s = capture_raw(flat, spec, e, 0).electrons.data[0];
  std::vector<double> means, variances;
  double peak_variance = 0, mean_at_peak = 0, plateau = 0;
  for (double share = 0.02; share < 1.3; share += share < 0.9 ? 0.04 : 0.004) {
    e.lux_seconds_per_film = share * spec.full_well_e / electrons_per_lux_s;
    const PairStats s = pair_stats(flat, spec, e);
    const double signal = s.mean - dark_stats.mean, noise = s.variance - dark_stats.variance;
    if (share <= 0.7) means.push_back(signal), variances.push_back(noise);
    if (s.variance > peak_variance) peak_variance = s.variance, mean_at_peak = signal;
    plateau = signal;  // the last, every photosite full
  }
  const double gain = slope(means, variances);
  // EMVA 1288: σ_d² = K²σ_read² + σ_q², the quantisation noise σ_q² = 1/12 DN².
  const double read_noise = std::sqrt(dark_stats.variance - 1.0 / 12) / gain;
  // The full well: where the photon-transfer curve's mean stops rising (the plateau of a frame
  // overexposed so that every photosite is full), in electrons through the recovered gain.
  const double full_well = plateau / gain;
  // EMVA 1288's saturation capacity, the mean at the variance's peak, lies a few shot-noise σ
  // (σ = √12000 ≈ 110 e⁻) below the full well by its definition: reported, bounded loosely.
  const double saturation_capacity = mean_at_peak / gain;
  std::printf(
      "photon transfer: K %.4f DN/e- (given %.4f), read noise %.3f e- (given %.3f), "
      "full well %.0f e- (given %.0f), EMVA saturation capacity %.0f e-\n",
      gain, spec.gain_dn_per_e, read_noise, spec.read_noise_e, full_well, spec.full_well_e,
      saturation_capacity);
  EXPECT_NEAR(gain / spec.gain_dn_per_e, 1, 0.02);
  EXPECT_NEAR(read_noise / spec.read_noise_e, 1, 0.02);
  EXPECT_NEAR(full_well / spec.full_well_e, 1, 0.02);
  EXPECT_LT(saturation_capacity, spec.full_well_e);
  EXPECT_GT(saturation_capacity, spec.full_well_e - 6 * std::sqrt(spec.full_well_e));
  // The mean dark level is the black level the DNG records.
  EXPECT_NEAR(dark_stats.mean, spec.black_level_dn, 0.05);
}

TEST(PhotonTransfer, DarkFramesGiveTheDarkCurrentAndItsDoubling) {
  SensorSpec spec = test_sensor();
  // One doubling temperature above the reference: twice the reference dark current.
  spec.temperature_c = spec.dark_reference_c + spec.dark_doubling_c;
  const Image dark(kSide, kSide, 3);
  std::vector<double> times, means;
  for (double t = 0.1; t <= 2.0; t += 0.1) {
    SensorExposure e;
    e.exposure_time_s = t;
    times.push_back(t);
    means.push_back(pair_stats(dark, spec, e).mean);
  }
  const double rate = slope(times, means) / spec.gain_dn_per_e;  // e⁻/s
  std::printf("dark current: %.3f e-/s (given %.3f at the reference, doubling to %.3f)\n", rate,
              spec.dark_current_e_s, 2 * spec.dark_current_e_s);
  EXPECT_NEAR(rate / (2 * spec.dark_current_e_s), 1, 0.02);
}

}  // namespace
}  // namespace obscura
