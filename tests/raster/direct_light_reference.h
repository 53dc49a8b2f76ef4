// What the rasterizer's agreement tests compare with: the tracer's direct lighting of the same
// scene and camera, one sample at each pixel centre, with its id AOV.
#pragma once

#include <memory>

#include "obscura/camera/camera.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/scene/scene.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/embree_scene.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"

namespace obscura::raster::test_images {

struct TracedImages {
  Image color, id;
};

// The camera at width × height with a pixel filter that puts every tracer sample at its centre.
inline Camera with_film(Camera camera, int width, int height) {
  camera.film.width_px = width;
  camera.film.height_px = height;
  camera.film.filter = BoxFilter{1e-6};
  return camera;
}

inline TracedImages trace_direct(const Scene& scene, const Camera& camera) {
  TraceScene trace_scene(scene, std::make_shared<EmbreeDevice>());
  Film film(camera.film.width_px, camera.film.height_px);
  AovBuffers aovs(camera.film.width_px, camera.film.height_px);
  render(trace_scene, camera, DirectLightingIntegrator(), {.samples_per_pixel = 1, .seed = 1}, film,
         {}, &aovs);
  return {film.to_image(), aovs.id()};
}

}  // namespace obscura::raster::test_images
