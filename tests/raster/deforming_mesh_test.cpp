// A deforming mesh (Mesh::deformation) moves in both renderers as a moving instance does: the
// rasterizer draws each frame at its time, the tracer's rays meet it where it is at theirs.
// The deformation slides a sphere 1 m along +X between t = 0 and t = 1 (positions worked out
// here); the expected places come from the camera and the sphere's geometry.
#include <gtest/gtest.h>

#include <memory>

#include "obscura/camera/frames.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/scene/shapes.h"
#include "obscura/trace/trace_scene.h"

namespace obscura::raster {
namespace {

Scene sliding_sphere() {
  Scene scene;
  scene.materials.resize(1);
  Mesh sphere = make_sphere(0.25f, 32);
  sphere.deformation.open_s = 0;
  sphere.deformation.close_s = 1;
  for (int k = 0; k <= 4; ++k) {
    std::vector<Point3f> p = sphere.positions;
    for (Point3f& v : p) v.x += float(k) / 4;
    sphere.deformation.positions.push_back(std::move(p));
  }
  scene.add_mesh(std::move(sphere));
  scene.camera.world_from_camera = world_from_camera_look_at({0, 0, 5}, {0, 0, 0});
  scene.camera.film.width_px = 96;
  scene.camera.film.height_px = 64;
  scene.camera.shutter = {.open_s = 0, .close_s = 1};
  return scene;
}

TEST(DeformingMesh, TheRasterizerDrawsEachFrameAtItsTime) {
  Scene scene = sliding_sphere();
  RasterSettings settings;
  settings.aovs = true;
  SceneRasterizer rasterizer(scene, settings);
  RenderTarget target = rasterizer.make_target(scene.camera);
  for (double t : {0.0, 0.3, 0.5, 1.0}) {
    RasterFrame frame;
    frame.time_s = t;
    rasterizer.render_frame(scene.camera, frame, target);
    double sum_x = 0;
    int n = 0;
    for (int y = 0; y < target.height(); ++y)
      for (int x = 0; x < target.width(); ++x)
        if (target.object_id_at(x, y) == 1) sum_x += x + 0.5, ++n;
    ASSERT_GT(n, 20) << "t = " << t;
    // Where the camera projects the moving centre (the off-axis ellipse's centroid lies up to
    // a quarter pixel farther out).
    EXPECT_NEAR(sum_x / n, scene.camera.project({t, 0, 0})->film_point.x, 0.3) << "t = " << t;
  }
}

TEST(DeformingMesh, TheTracersRaysMeetItWhereItIsAtTheirTime) {
  Scene scene = sliding_sphere();
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  EXPECT_TRUE(trace.has_motion());
  for (double t : {0.0, 0.3, 0.5, 1.0}) {
    // Straight down −Z onto where the centre is at t: the sphere's front at z = 0.25 (an
    // equator vertex of the tessellation lies exactly there).
    Ray down;
    down.origin = {float(t), 0.f, 5.f};
    down.direction = {0, 0, -1};
    down.time = float(t);
    std::optional<SurfaceHit> hit = trace.intersect(down);
    ASSERT_TRUE(hit) << "t = " << t;
    EXPECT_NEAR(hit->position.z, 0.25, 2e-3) << "t = " << t;
    EXPECT_NEAR(hit->shading_normal.z, 1, 1e-2) << "t = " << t;
    // Where the sphere was at rest, it has gone by t = 1 (it moved 1 m; radius 0.25 m).
    Ray rest = down;
    rest.origin.x = 0;
    EXPECT_EQ(trace.intersect(rest).has_value(), t < 0.25) << "t = " << t;
  }
}

}  // namespace
}  // namespace obscura::raster
