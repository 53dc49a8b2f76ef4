// What a caller chooses of the rasterizer's frame (raster/render.h), apart from the rasterizer:
// light enough for every settings struct that carries it.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string_view>

#include "obscura/film/image.h"
#include "obscura/film/work_share.h"

namespace obscura::raster {

enum class ShadingMode {
  kFlat,        // per-pixel lighting with each triangle's own (face) normal
  kGouraud,     // lighting at the vertices, interpolated
  kPhong,       // per-pixel lighting with interpolated normals; materials keep their lobes
  kBlinnPhong,  // as kPhong, and Phong materials use the half-vector lobe
};
// "flat", "gouraud", "phong", "blinn-phong" (as the command line and Python name them); nothing
// for any other name.
std::optional<ShadingMode> parse_shading_mode(std::string_view name);

enum class DepthOfFieldMethod {
  kOff,         // every frame through the lens centre: sharp (motion blur still accumulates)
  kAccumulate,  // frames through jittered lens points, averaged
  kPost,        // one frame blurred by its z-buffer's circle of confusion
};
// "off", "accumulate", "post"; nothing for any other name.
std::optional<DepthOfFieldMethod> parse_depth_of_field_method(std::string_view name);

struct RenderSettings {
  int msaa_samples = 1;  // 1, 4 or 8
  ShadingMode shading = ShadingMode::kPhong;
  bool cull_back_faces = false;
  bool wireframe = false;      // triangle edges over the shaded image
  int shadow_map_size = 1024;  // texels per side; 0: no shadows
  DepthOfFieldMethod depth_of_field = DepthOfFieldMethod::kAccumulate;
  int effect_samples = 32;  // frames accumulated for depth of field and motion blur (≥ 1)
  uint64_t seed = 0;        // the lens points and shutter times of accumulated frames
  // Stopping an accumulation early (after at least one frame): 0 = no time limit.
  double time_limit_s = 0;
  const std::atomic<bool>* cancel = nullptr;
  // The tiles (of kTileSize) this process draws when several draw the frame together.
  WorkShare share = {};
};

// The view depth of the frame nearest mid-shutter and each pixel's circle of confusion through
// the camera drawn (diameter, pixels), with its pixel aspect: all the post-process needs.
struct PostDepthOfFieldInputs {
  Image view_depth, coc_px;
  double pixel_aspect = 1;
};

}  // namespace obscura::raster
