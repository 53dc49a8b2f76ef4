// A raw image sensor's description: the photosites' size, the colour filter array in front of
// them, their spectral quantum efficiency, and every source of noise and non-linearity between
// the photons that arrive and the digital numbers (DN) the ADC reports. Plain data; the
// simulation is sensor_capture.h, the equations docs/sensor.md.
//
// The JSON camera's "sensor" block, the command line's `--raw-sensor KEY=VALUE,…` and the Python
// `sensor={…}` dictionary all name the fields as set_sensor_field does, with the same units.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace obscura {

// The 2 × 2 Bayer tiles, named by their colours in reading order (top-left, top-right,
// bottom-left, bottom-right), and a sensor without a colour filter.
enum class CfaPattern { kRggb, kBggr, kGrbg, kGbrg, kMonochrome };

// The colour (0 red, 1 green, 2 blue) of pixel (x, y) under `pattern`; 1 (its one channel,
// counted as green) for a monochrome sensor.
int cfa_color(CfaPattern pattern, int x, int y);
// "RGGB", "BGGR", "GRBG", "GBRG" or "mono"; parse_cfa_pattern takes them in any case (and
// "monochrome"); throws obscura::Error naming `field` otherwise.
std::string_view cfa_pattern_name(CfaPattern pattern);
CfaPattern parse_cfa_pattern(std::string_view text, const std::string& field = "sensor.cfa");

// One channel's spectral quantum efficiency as a Gaussian band: QE(λ) = peak · exp(−(λ − μ)² /
// (2σ²)), the parametric model of ISETCam's sensor tutorials. peak ∈ (0, 1].
struct QeBand {
  double peak = 0.5;
  double center_nm = 550;
  double width_nm = 40;  // σ
};

struct SensorSpec {
  double pixel_pitch_um = 4.0;  // photosite spacing, square pixels
  double fill_factor = 1.0;     // share of the pixel that collects light (microlenses: ~1)
  CfaPattern cfa = CfaPattern::kRggb;
  // Red, green, blue filters' QE (a monochrome sensor uses `mono_qe`). Defaults: bands with the
  // peaks and widths of a typical CMOS colour sensor (ISETCam's default sensor is of this shape).
  std::array<QeBand, 3> qe = {QeBand{0.45, 600, 32}, QeBand{0.55, 535, 38}, QeBand{0.45, 460, 30}};
  QeBand mono_qe{0.65, 550, 100};
  double full_well_e = 20000;     // electrons a photosite holds before it saturates
  double read_noise_e = 2.5;      // σ of the read-out noise, electrons
  double dark_current_e_s = 1.0;  // electrons per second per pixel at the reference temperature
  double temperature_c = 25;      // the sensor's temperature
  double dark_reference_c = 25;   // where dark_current_e_s holds
  double dark_doubling_c = 6.3;   // dark current doubles every this many °C (silicon: 6–7 °C)
  double prnu = 0.01;             // photo-response non-uniformity: σ of the per-pixel gain
  double dsnu_e_s = 0.2;          // dark-signal non-uniformity: σ of the per-pixel dark current
  double gain_dn_per_e = 0.25;    // conversion gain at the base ISO (EMVA 1288's K), DN per e⁻
  double base_iso = 100;          // the ISO at which gain_dn_per_e holds (ISO multiplies it)
  double black_level_dn = 256;    // offset added before the ADC
  int adc_bits = 14;              // 1..16 (the raw mosaic is stored in 16 bits)
  uint64_t seed = 1;              // the fixed-pattern noise (PRNU, DSNU) of this sensor

  // Throws obscura::Error naming the first invalid field ("sensor.read_noise_e: …"): negative
  // noise, zero full well, QE outside (0, 1], ADC bits outside 1..16, a black level at or above
  // the ADC's range, NaN or infinity anywhere. Validation errors are obscura::RequestError.
  void validate() const;
};

// Sets one field by its name from text, as the JSON block, `--raw-sensor` and Python name them:
// pixel_pitch_um, fill_factor, cfa, qe_red / qe_green / qe_blue / qe_mono (peak), qe_*_nm
// (centre), qe_*_width_nm, full_well_e, read_noise_e, dark_current_e_s, temperature_c,
// dark_reference_c, dark_doubling_c, prnu, dsnu_e_s, gain_dn_per_e, base_iso, black_level_dn,
// adc_bits, seed. Throws obscura::Error naming "sensor.NAME" for an unknown name or a value that
// is not a number (ranges are validate()'s).
void set_sensor_field(SensorSpec& spec, std::string_view name, std::string_view value);
// The same for a number (every field but cfa); what JSON and Python hand over.
void set_sensor_number(SensorSpec& spec, std::string_view name, double value);
// Every field name set_sensor_field takes, comma-separated (for messages and help).
std::string sensor_field_names();
// Parses "KEY=VALUE,KEY=VALUE,…" over `spec` (an empty text changes nothing), then validates.
void apply_sensor_fields(SensorSpec& spec, std::string_view text);

}  // namespace obscura
