#include "sensor_options.h"

namespace obscura::app {

void add_sensor_options(CLI::App& render, SensorOptions& o) {
  const std::string group = "Raw sensor and metering";
  render
      .add_option("--raw-sensor", o.sensor,
                  "Capture the frame with a raw sensor: 'on' (the scene camera's \"sensor\" "
                  "block, else the defaults) or KEY=VALUE,… over it (cfa=RGGB|BGGR|GRBG|GBRG|mono, "
                  "pixel_pitch_um, fill_factor, full_well_e, read_noise_e, dark_current_e_s, "
                  "temperature_c, prnu, dsnu_e_s, gain_dn_per_e, base_iso, black_level_dn, "
                  "adc_bits, seed, qe_red, …; docs/sensor.md). -o x.dng writes the raw DNG with "
                  "its ground truth; other formats the developed image")
      ->group(group);
  render
      .add_option("--demosaic", o.demosaic,
                  "How a raw capture is demosaiced for a developed image or a --linear-dng: "
                  "bilinear or malvar (Malvar-He-Cutler)")
      ->capture_default_str()
      ->group(group);
  render.add_flag("--linear-dng", o.linear_dng, "Write the DNG demosaiced (LinearRaw), not CFA")
      ->group(group);
  render
      .add_option("--metering", o.metering,
                  "Meter the frame (average, center-weighted or spot; ISO 2720, K = 12.5) and "
                  "report its EV100 in the summary and the file's metadata; the pattern "
                  "--exposure-mode auto meters with (default average)")
      ->group(group);
}

}  // namespace obscura::app
