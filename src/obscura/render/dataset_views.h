// The views of a dataset (`obscura dataset --views ...`, Python's render_dataset): cameras placed
// around a scene or along a path, each named by its index (view_0000, view_0001, ...).
//
//   orbit:N[:ELEVATION]  N views on a horizontal circle around the centre of the scene's bounds,
//                        ELEVATION degrees above it (default 20), the first in front (+Z), then
//                        turning counter-clockwise seen from above (increasing azimuth)
//   sphere:N             N views on a sphere around the same centre, a Fibonacci lattice from
//                        the top down (view k at height 1 − (2k + 1)/N, azimuth k · 137.5°)
//   path:N:FILE          N views along a camera path: FILE has one keyframe a line, "X Y Z TX TY
//                        TZ" (the camera's position and the point it looks at; '#' comments);
//                        the views are evenly spaced by distance along the positions' polyline,
//                        the first and last at its ends (a path that does not move: by keyframe)
//   cameras              every camera of the scene, in the scene's order
//
// Orbit and sphere views look at the centre of the bounds from the distance at which the
// bounding sphere fills the narrower field of view (r / sin(fov/2), times 1.05), up = world +Y.
// Every view shares the camera the request resolves (its projection, lens, film, shutter, ...);
// only the pose differs, and "cameras" resolves the request once per scene camera.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/render/camera_request.h"
#include "obscura/scene/scene.h"

namespace obscura {

struct DatasetView {
  std::string name;  // "view_0000", ...
  Camera camera;
};

// The view's name for index i: "view_" and at least four digits.
std::string dataset_view_name(size_t index);

// The views `spec` asks for (the forms above). Throws RequestError for a malformed spec, a
// request that places the camera itself (--position, --look-at, --up), a camera without a field
// of view (orthographic) for orbit or sphere views, an empty scene; obscura::Error for a path
// file that cannot be read or is malformed (naming file:line).
std::vector<DatasetView> dataset_views(const Scene& scene, const CameraRequest& request,
                                       const std::string& spec,
                                       std::optional<int> width_px = std::nullopt,
                                       std::optional<int> height_px = std::nullopt,
                                       std::vector<std::string>* notes = nullptr);

// The same around a camera already resolved (Python's render_dataset): orbit, sphere and path
// views take `base` with their poses; "cameras" takes each scene camera with `base`'s film.
std::vector<DatasetView> dataset_views(const Scene& scene, const Camera& base,
                                       const std::string& spec);

// The most views a spec may ask for.
inline constexpr int kMaxDatasetViews = 100000;

}  // namespace obscura
