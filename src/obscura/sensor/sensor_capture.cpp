#include "obscura/sensor/sensor_capture.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "obscura/math/number_text.h"
#include "obscura/math/request_error.h"
#include "obscura/math/rng.h"
#include "obscura/sensor/sensor_noise.h"

namespace obscura {

namespace {

// Keys of the noise sources: the fixed pattern hangs on the sensor's seed alone, the temporal
// noise on the frame's seed too.
constexpr uint64_t kPrnuKey = 0x9e1f, kDsnuKey = 0xd5a0, kTemporalKey = 0x7e3b;

void check_exposure(const SensorExposure& e) {
  auto fail = [](const char* field, double v) {
    throw RequestError(std::string("sensor exposure.") + field,
                       "must be a positive finite number; got " + number_text(v));
  };
  if (!(e.exposure_time_s > 0) || !std::isfinite(e.exposure_time_s))
    fail("exposure_time_s", e.exposure_time_s);
  if (!(e.iso > 0) || !std::isfinite(e.iso)) fail("iso", e.iso);
  if (!(e.lux_seconds_per_film > 0) || !std::isfinite(e.lux_seconds_per_film))
    fail("lux_seconds_per_film", e.lux_seconds_per_film);
}

}  // namespace

RawCapture capture_raw(const Image& film, const SensorSpec& spec, const SensorExposure& exposure,
                       uint64_t frame_seed) {
  spec.validate();
  check_exposure(exposure);
  if (film.channels < 3 || film.width <= 0 || film.height <= 0)
    throw Error("sensor", "needs an RGB film; got " + std::to_string(film.width) + "x" +
                              std::to_string(film.height) + "x" + std::to_string(film.channels));
  RawCapture c;
  c.width = film.width;
  c.height = film.height;
  c.cfa = spec.cfa;
  c.response = sensor_response(spec);
  c.black_level = spec.black_level_dn;
  c.gain_dn_per_e = spec.gain_dn_per_e * exposure.iso / spec.base_iso;
  const double adc_max = std::exp2(spec.adc_bits) - 1;
  // A saturated photosite reads its full well: black + K·FW, or the ADC's largest value.
  c.white_level = std::min(adc_max, std::round(c.black_level + c.gain_dn_per_e * spec.full_well_e));
  const double area_m2 = spec.pixel_pitch_um * spec.pixel_pitch_um * 1e-12 * spec.fill_factor;
  const double h = exposure.lux_seconds_per_film;
  const Matrix3d& m = c.response.electrons_per_lux_s_m2;
  c.electrons_per_film = area_m2 * h * (m.m[1][0] + m.m[1][1] + m.m[1][2]);
  const double dark_rate =
      spec.dark_current_e_s *
      std::exp2((spec.temperature_c - spec.dark_reference_c) / spec.dark_doubling_c);
  const double t = exposure.exposure_time_s;

  c.raw.assign(size_t(c.width) * c.height, 0);
  c.irradiance_lux = Image(c.width, c.height, 3);
  c.irradiance_lux.channel_names = {"R", "G", "B"};
  c.electrons = Image(c.width, c.height, 1);
  c.electrons.channel_names = {"electrons"};
  const uint64_t prnu_key = hash_words(spec.seed, kPrnuKey);
  const uint64_t dsnu_key = hash_words(spec.seed, kDsnuKey);
  const uint64_t temporal_key = hash_words(spec.seed, kTemporalKey, frame_seed);

  tbb::parallel_for(tbb::blocked_range<int>(0, c.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < c.width; ++x) {
        const size_t index = size_t(y) * c.width + x;
        const int k = cfa_color(spec.cfa, x, y);
        const Vec3d v = {film.at(x, y, 0), film.at(x, y, 1), film.at(x, y, 2)};
        for (int ch = 0; ch < 3; ++ch)
          c.irradiance_lux.at(x, y, ch) = float(std::max(0.0, v[size_t(ch)]) * h / t);
        double mean = 0;
        for (int ch = 0; ch < 3; ++ch)
          mean += m.m[size_t(k)][size_t(ch)] * std::max(0.0, v[size_t(ch)]);
        mean *= area_m2 * h;
        if (!std::isfinite(mean)) mean = 0;  // a NaN film pixel collects nothing
        c.electrons.data[index] = float(mean);

        NoiseStream prnu(prnu_key, index), dsnu(dsnu_key, index), temporal(temporal_key, index);
        const double gain = std::max(0.0, 1 + spec.prnu * prnu.normal());
        const double dark = std::max(0.0, dark_rate + spec.dsnu_e_s * dsnu.normal()) * t;
        double electrons = temporal.poisson(mean * gain) + temporal.poisson(dark);
        electrons = std::min(electrons, spec.full_well_e);
        const double read = spec.read_noise_e * temporal.normal();
        const double dn = std::round(c.black_level + c.gain_dn_per_e * (electrons + read));
        // The read-out clips at the white level too: a full photosite reads exactly white (plus
        // read noise it would stray above it, and developers take white as the clip).
        c.raw[index] = uint16_t(std::clamp(dn, 0.0, c.white_level));
      }
  });
  return c;
}

Image raw_image(const RawCapture& capture) {
  Image image(capture.width, capture.height, 1);
  image.channel_names = {"raw"};
  for (size_t i = 0; i < capture.raw.size(); ++i) image.data[i] = float(capture.raw[i]);
  return image;
}

}  // namespace obscura
