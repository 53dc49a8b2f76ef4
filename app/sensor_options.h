// `obscura render --raw-sensor`: the raw sensor behind the film (docs/sensor.md), DNG output, and
// metering and automatic exposure (`--metering`, `--exposure-mode auto`).
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "obscura/film/metering.h"
#include "obscura/sensor/isp.h"
#include "obscura/sensor/sensor_capture.h"

namespace obscura::app {

struct SensorOptions {
  std::optional<std::string> sensor;    // --raw-sensor: "on" or KEY=VALUE,…
  std::string demosaic = "malvar";      // --demosaic
  bool linear_dng = false;              // --linear-dng
  std::optional<std::string> metering;  // --metering MODE
  // Resolved before rendering (resolve_sensor): the sensor over the scene camera's block, the
  // camera's exposure as plain numbers, what the meter read.
  std::optional<SensorSpec> spec;
  SensorExposure exposure;
  bool auto_exposure = false;  // --exposure-mode auto
  std::optional<MeteringMode> metering_mode;
  std::optional<double> metered_ev100;
  std::string exposure_note;  // the auto exposure's choice, for the summary
  double exposure_scale = 1;  // the resolved camera's, to meter a finished frame in cd/m²
};

void add_sensor_options(CLI::App& render, SensorOptions& options);

}  // namespace obscura::app
