// What `obscura render` was asked to do: every option, as parsed.
#pragma once

#include <cstdint>
#include <string>

#include "camera_options.h"
#include "display_options.h"
#include "glare_options.h"
#include "ground_truth_output.h"
#include "raster_effects_options.h"
#include "raster_options.h"
#include "reyes_options.h"
#include "scene_choice_options.h"
#include "sensor_options.h"
#include "tracer_options.h"

namespace obscura::app {

struct RenderOptions {
  std::string scene;
  std::string output = "render.png";
  int width = 512, height = 512;
  int spp = 32;
  int threads = 0;
  uint64_t seed = 0;
  bool quiet = false;
  bool list_scenes = false;
  std::string environment = "auto";
  double environment_intensity = 1;
  std::string gltf_variant;  // KHR_materials_variants: a variant's name; empty = the defaults
  std::string shard;         // --shard I/N: render part I of N to a partial film; empty = whole
  std::string frames;        // --frames A:B[:STEP]: a sequence; empty = one frame
  double fps = 24;           // --fps: frame n is exposed around n / fps seconds
  CameraOverrides camera;
  SceneChoiceOptions choice;
  DisplayOptions display;
  TracerOptions tracer;
  RasterOptions raster;
  RasterEffectsOptions raster_effects;
  ReyesOptions reyes;  // --reyes-*
  GlareOptions glare;               // --glare, --glare-strength, --glare-radius
  bool flare = false;               // --flare: ghost flares of a lens-system camera
  bool stats = false;               // --stats: the renderer's own counters after the summary
  GroundTruthOptions ground_truth;  // --ground-truth, --flow-times
  std::string display_server;       // --display-server HOST:PORT: push the frame to tev
  SensorOptions sensor;  // --raw-sensor, --metering, --exposure-mode auto (docs/sensor.md)
  // Which options were given on the command line: those override the scene file's settings.
  bool width_given = false, height_given = false, spp_given = false, seed_given = false;
};

}  // namespace obscura::app
