// The render loop with the full camera: reconstruction filters, depth of field, motion and
// crop windows stay deterministic, and the filter weights leave flat regions flat.
#include "obscura/trace/render.h"

#include <gtest/gtest.h>

#include <memory>

#include <tbb/global_control.h>

#include "obscura/camera/frames.h"
#include "obscura/math/error.h"
#include "obscura/scene/builtin_scenes.h"
#include "obscura/trace/direct_lighting.h"

namespace obscura {
namespace {

std::vector<float> render_pixels(const Scene& scene, const Camera& camera, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Bounds2i crop = camera.film.crop_pixels();
  Film film(crop.width(), crop.height());
  render(trace, camera, DirectLightingIntegrator(), {.samples_per_pixel = 3, .seed = 5}, film);
  return film.to_image().data;
}

TEST(RenderCamera, DepthOfFieldFilterAndMotionAreBitIdenticalAcrossThreadCounts) {
  Scene scene = make_cornell_box();
  Camera& c = scene.camera;
  c.film.width_px = 40;
  c.film.height_px = 32;
  c.film.filter = MitchellFilter{};
  c.lens.depth_of_field = true;
  c.lens.f_number = 1.4;
  c.lens.aperture.blades = 5;
  Point3d eye(0.278, 0.273, -0.8);
  c.world_from_camera = AnimatedTransform(
      {{0, world_from_camera_look_at(eye, eye + Vector3d(0, 0, 1))},
       {1, world_from_camera_look_at(eye + Vector3d(0.05, 0, 0), eye + Vector3d(0, 0, 1))}});
  c.shutter = {.open_s = 0, .close_s = 1};
  EXPECT_EQ(render_pixels(scene, c, 1), render_pixels(scene, c, 2));
}

TEST(RenderCamera, FilterWeightsLeaveAUniformEmitterUniform) {
  // A camera facing a large emitter: every sample sees radiance 2, so every pixel must be 2
  // whatever the filter, negative Mitchell lobes included.
  Scene scene;
  scene.name = "wall";
  Material emitter;
  emitter.name = "emitter";
  emitter.model = EmissiveMaterial{};
  emitter.emission = Rgb(2);
  scene.materials = {emitter};
  Mesh wall;
  wall.name = "wall";
  wall.positions = {{-50, -40, -1}, {60, -50, -1}, {50, 50, -1}, {-40, 60, -1}};
  wall.indices = {0, 1, 2, 0, 2, 3};
  scene.add_mesh(wall);
  Camera& c = scene.camera;
  c.film.width_px = 12;
  c.film.height_px = 10;
  for (PixelFilter f : {PixelFilter(BoxFilter{}), PixelFilter(TentFilter{}),
                        PixelFilter(GaussianFilter{}), PixelFilter(MitchellFilter{})}) {
    c.film.filter = f;
    {
      std::vector<float> pixels = render_pixels(scene, c, 2);
      for (size_t i = 0; i < pixels.size(); ++i)
        EXPECT_NEAR(pixels[i], 2.0f, 1e-5f) << filter_name(f) << " value " << i;
    }
  }
  c.exposure.compensation_ev = -1;
  for (float v : render_pixels(scene, c, 2)) EXPECT_NEAR(v, 1.0f, 1e-5f);
}

TEST(RenderCamera, FilmMustMatchTheCrop) {
  Scene scene = make_cornell_box();
  scene.camera.film.width_px = 20;
  scene.camera.film.height_px = 20;
  scene.camera.film.crop = {.x_min = 0, .y_min = 0, .x_max = 0.5, .y_max = 1};
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Film wrong(20, 20);
  EXPECT_THROW(render(trace, scene.camera, DirectLightingIntegrator(), {}, wrong), Error);
}

}  // namespace
}  // namespace obscura
