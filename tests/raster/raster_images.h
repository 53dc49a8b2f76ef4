// What the rasterizer tests compare: a scene rasterized with its AOVs, and where an id image
// changes object (the pixels where two renderers may disagree without either being wrong).
#pragma once

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

}  // namespace obscura::raster::test_images
