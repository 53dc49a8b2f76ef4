#include "sensor_frame.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "display_options.h"
#include "frame_render.h"
#include "obscura/io/dng_file.h"
#include "obscura/io/sensor_json.h"
#include "obscura/math/number_text.h"
#include "obscura/render/auto_exposure.h"
#include "obscura/render/sensor_exposure.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

// Samples per pixel of the metering pass: enough for a mean over the frame.
constexpr int kMeteringSpp = 4;

// Whether the output is a DNG, without judging other names (check_output_path does, later, with
// the messages every output gets).
bool dng_output(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".dng";
}

}  // namespace

void take_sensor_requests(RenderOptions& options) {
  SensorOptions& s = options.sensor;
  if (options.camera.exposure_mode && *options.camera.exposure_mode == "auto") {
    s.auto_exposure = true;
    options.camera.exposure_mode = "radiance";
  }
  if (s.metering) s.metering_mode = parse_metering_mode(*s.metering);
  if (s.auto_exposure && !s.metering_mode) s.metering_mode = MeteringMode::kAverage;
  parse_demosaic_method(s.demosaic);  // a bad name fails before rendering
  if (!s.sensor && dng_output(options.output)) s.sensor = "on";
  if (s.linear_dng && !dng_output(options.output))
    throw UsageError("--linear-dng shapes a DNG output: give -o NAME.dng");
}

void resolve_sensor(RenderOptions& options, Scene& scene) {
  SensorOptions& s = options.sensor;
  if (s.auto_exposure) {
    const double compensation = options.camera.exposure_ev.value_or(0);
    RenderOptions pass = options;
    pass.spp = std::min(options.spp, kMeteringSpp);
    pass.tracer.aovs = false;
    pass.quiet = true;
    const Camera camera = scene.camera;
    scene.camera = metering_camera(camera);
    RenderedFrame frame = render_frame(scene, pass, WorkShare{});
    scene.camera = camera;
    const MeteredExposure m = meter_for(camera, frame.finished(), *s.metering_mode, compensation);
    apply_exposure(scene.camera, m.settings);
    s.metered_ev100 = m.ev100;
    // As a camera shows it: f/2.8, 1/125 s (or 2.5 s), ISO 400.
    const double t = m.settings.exposure_time_s;
    char time[32], note[160];
    if (t < 1)
      std::snprintf(time, sizeof time, "1/%.3g s", 1 / t);
    else
      std::snprintf(time, sizeof time, "%.3g s", t);
    std::snprintf(note, sizeof note, "f/%.3g, %s, ISO %.0f", m.settings.f_number, time,
                  m.settings.iso);
    s.exposure_note = note;
  }
  s.exposure_scale = scene.camera.exposure_scale();
  if (!s.sensor) return;
  SensorSpec spec = scene_camera_sensor(options.scene, scene.camera.name).value_or(SensorSpec{});
  if (*s.sensor != "on") apply_sensor_fields(spec, *s.sensor);
  spec.validate();
  s.spec = spec;
  s.exposure = sensor_exposure(scene.camera);
}

void add_metering_metadata(const SensorOptions& s, ImageMetadata& metadata) {
  if (s.metered_ev100) {
    metadata.attributes.emplace_back("obscura:metered_ev100", number_text(*s.metered_ev100));
    metadata.attributes.emplace_back("obscura:metering",
                                     std::string(metering_mode_name(*s.metering_mode)));
  }
  if (!s.exposure_note.empty())
    metadata.attributes.emplace_back("obscura:auto_exposure", s.exposure_note);
}

void meter_finished(SensorOptions& s, const Image& finished, double exposure_scale) {
  if (!s.metering_mode || s.metered_ev100) return;
  Image radiance = finished;
  for (float& v : radiance.data) v = float(v / exposure_scale);
  s.metered_ev100 = metered_ev100(metered_luminance(radiance, *s.metering_mode));
}

std::vector<std::string> write_sensor_frame(const RenderOptions& options, const std::string& output,
                                            const Image& finished,
                                            ImageWriteOptions write_options) {
  const SensorOptions& s = options.sensor;
  const RawCapture capture = capture_raw(finished, *s.spec, s.exposure, options.seed);
  const DemosaicMethod method = parse_demosaic_method(s.demosaic);
  if (image_format_for_path(output) == ImageFormat::kDng) {
    DngWriteOptions dng;
    dng.linear = s.linear_dng;
    dng.demosaic = method;
    dng.metadata = write_options.metadata;
    return write_dng(output, capture, dng);
  }
  report_write(output, write_image(output, develop_raw(capture, method), write_options),
               options.quiet);
  return {output};
}

}  // namespace obscura::app
