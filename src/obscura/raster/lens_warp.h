// Rasterizing cameras that have no projection matrix: calibrated lenses with distortion,
// fisheyes, panoramas. Straight lines do not stay straight through such a lens, so no matrix
// draws it. The rasterizer instead draws pinhole views that together see everything the camera's
// pixels see — one view fitted around the field when every ray is within 60° of the axis, else
// the faces of a cube around the camera, only those the pixels look into — at `oversampling`
// times the camera's finest pixel density; then each output pixel averages subpixels²
// bilinear lookups of the views along the camera's exact rays (the tracer's rays through the
// lens centre, from the same inverse map).
//
// Error bound: every lookup follows the exact ray, so nothing is displaced; the views' bilinear
// reconstruction spreads a sharp edge over 1/oversampling of an output pixel, symmetrically, so
// an edge's 50 % crossing — and a corner — lands where the tracer's does to within
// 1/(2·oversampling) px in the worst case and far less on average (tests: checkerboard corners in
// both renderers' images agree to 0.1 px).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/film/film.h"
#include "obscura/film/image.h"
#include "obscura/raster/scene_rasterizer.h"

namespace obscura::raster {

struct LensWarpSettings {
  int oversampling = 2;         // view pixels per output pixel, along each axis, at least
  int subpixels = 2;            // lookups per output pixel along each axis
  int max_view_side_px = 8192;  // a view's resolution cap (a warning says when it binds)
  int part = 0, parts = 1;      // the output tiles drawn, as RenderTarget::set_share
};

// The pinhole views covering `camera`'s crop: perspective cameras at the camera's position, turned
// towards their part of the field.
struct LensViews {
  std::vector<Camera> views;
  std::vector<Transform> camera_from_view;  // each view's turn, in the camera's frame
  bool cube = false;                        // views are cube faces (else one fitted view)
  std::vector<std::string> warnings;
};
// Throws obscura::Error when the camera's crop sees nothing (every ray outside the lens' field).
LensViews plan_lens_views(const Camera& camera, const LensWarpSettings& settings);

struct LensRender {
  // With the rasterizer's AOVs on: the tracer's normal, depth (along the optical axis), range
  // (along the ray) and id images, looked up at each pixel centre's ray (nearest view pixel).
  std::optional<Image> normal, depth, range, id;
  std::vector<std::string> warnings;
};
// Renders `camera` (any projection) through its lens views into `film` (the crop's size), one
// sample of weight 1 per drawn pixel, as SceneRasterizer::render does for pinhole cameras.
LensRender render_through_lens(const SceneRasterizer& rasterizer, const Camera& camera,
                               const LensWarpSettings& settings, Film& film);

}  // namespace obscura::raster
