// What the rasterizer tests compare: a scene rasterized with its AOVs, and where an id image
// changes object (the pixels where two renderers may disagree without either being wrong).
#pragma once

#include <algorithm>
#include <cmath>

#include "obscura/film/film.h"
#include "obscura/raster/scene_rasterizer.h"

namespace obscura::raster::test_images {

struct RasterImages {
  Image color, id, normal;
};

// `scene` through `camera` with `settings` (AOVs turned on).
inline RasterImages rasterize_with_aovs(const Scene& scene, const Camera& camera,
                                        RasterSettings settings = {}) {
  settings.aovs = true;
  SceneRasterizer rasterizer(scene, settings);
  RenderTarget target = rasterizer.make_target(camera);
  Film film(target.width(), target.height());
  rasterizer.render(camera, film, &target);
  return {film.to_image(), id_image(target), normal_image(target)};
}

// Whether a pixel lies on a silhouette: some 8-neighbour sees another object.
inline bool on_silhouette(const Image& id, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= id.width || ny >= id.height) continue;
      if (id.at(nx, ny, 0) != id.at(x, y, 0)) return true;
    }
  return false;
}

// How two renders of the same objects agree in colour where both see the same object at a pixel
// centre, away from silhouettes: the relative difference per channel (absolute against 0.02 in
// the dark), and per object id 0–2 the pixels that are lit (a channel above 0.05).
struct ColourAgreement {
  double max_relative = 0, mean_relative = 0;
  int compared = 0;
  int lit[3] = {0, 0, 0};
};
inline ColourAgreement compare_colours(const Image& color, const Image& id,
                                       const Image& other_color, const Image& other_id) {
  ColourAgreement a;
  double sum = 0;
  for (int y = 0; y < color.height; ++y)
    for (int x = 0; x < color.width; ++x) {
      float object = id.at(x, y, 0);
      if (object < 0 || other_id.at(x, y, 0) != object || on_silhouette(id, x, y)) continue;
      bool lit = false;
      for (int c = 0; c < 3; ++c) {
        double t = color.at(x, y, c), r = other_color.at(x, y, c);
        double relative = std::abs(r - t) / std::max(t, 0.02);
        a.max_relative = std::max(a.max_relative, relative);
        sum += relative;
        lit = lit || t > 0.05;
      }
      if (lit && object < 3) ++a.lit[int(object)];
      ++a.compared;
    }
  a.mean_relative = a.compared ? sum / (3 * a.compared) : 0;
  return a;
}

}  // namespace obscura::raster::test_images
