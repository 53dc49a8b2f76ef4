// `obscura render --glare`: diffraction glare on the finished HDR frame, either renderer
// (render/camera_glare.h; docs/camera.md, "Diffraction glare").
#pragma once

#include <optional>

#include <CLI/CLI.hpp>

#include "obscura/film/glare.h"
#include "obscura/scene/scene.h"

namespace obscura::app {

struct GlareOptions {
  bool on = false;
  std::optional<double> strength;  // --glare-strength (implies --glare)
  std::optional<int> radius_px;    // --glare-radius
};

void add_glare_options(CLI::App& render, GlareOptions& options);

// The glare asked for by the options, else by the scene file's render settings; nothing when
// neither asks.
std::optional<GlareSettings> glare_settings(const GlareOptions& options,
                                            const SceneRenderSettings& scene);

}  // namespace obscura::app
