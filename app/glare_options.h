// `obscura render --glare`: diffraction glare on the finished HDR frame, either renderer
// (render/camera_glare.h; docs/camera.md, "Diffraction glare").
#pragma once

#include <optional>

#include <CLI/CLI.hpp>

namespace obscura::app {

struct GlareOptions {
  bool on = false;
  std::optional<double> strength;  // --glare-strength (implies --glare)
  std::optional<int> radius_px;    // --glare-radius
};

void add_glare_options(CLI::App& render, GlareOptions& options);

}  // namespace obscura::app
