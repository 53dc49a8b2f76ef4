// RenderSession: frames rendered through one session are the frames render_frame renders alone,
// bit for bit, while the tracer's scene is compiled once for a scene where nothing moves and
// again (or brought up to date) only when a moving scene's exposure changes.
#include "obscura/render/render_session.h"

#include <gtest/gtest.h>

#include <cstring>

#include "obscura/io/scene_loader.h"
#include "obscura/render/ground_truth_frame.h"

namespace obscura {
namespace {

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

// The scene's camera, small, exposed around `time_s` for 1/60 s.
Camera camera_at(const Scene& scene, double time_s) {
  Camera camera = scene.camera;
  camera.film.width_px = 32;
  camera.film.height_px = 24;
  camera.shutter.open_s = time_s - 1.0 / 120;
  camera.shutter.close_s = time_s + 1.0 / 120;
  return camera;
}

TEST(RenderSession, AStillSceneCompilesOnceForEveryExposure) {
  const Scene scene = load_scene("cornell-box");
  RenderSession session(scene);
  const FrameSettings settings{.samples_per_pixel = 2, .seed = 3};
  for (double time : {0.0, 0.5, 1.0}) {
    const Camera camera = camera_at(scene, time);
    const RenderedFrame kept = session.render(camera, settings, true);
    const RenderedFrame alone = render_frame(scene, camera, settings, true);
    EXPECT_TRUE(same_bits(kept.finished(), alone.finished())) << "at " << time << " s";
    EXPECT_TRUE(same_bits(kept.aovs->depth(), alone.aovs->depth()));
  }
  EXPECT_EQ(session.compilations(), 1);
}

TEST(RenderSession, AMovingSceneCompilesAgainOnlyWhenTheExposureChanges) {
  const Scene scene = load_scene("motion-blur");
  RenderSession session(scene);
  const FrameSettings settings{.samples_per_pixel = 2, .seed = 3};
  const double times[] = {0.0, 0.0, 0.25, 0.25, 0.5};
  for (double time : times) {
    const Camera camera = camera_at(scene, time);
    EXPECT_TRUE(same_bits(session.render(camera, settings, false).finished(),
                          render_frame(scene, camera, settings, false).finished()))
        << "at " << time << " s";
  }
  // Three intervals: a new compilation, or where the sphere's motion keeps its time-step count
  // over the new one, the same compilation brought up to date in place.
  EXPECT_EQ(session.compilations() + session.updates(), 3);

  // The rasterizer's compilation is the scene as it is: it serves every exposure.
  RenderSession raster(scene);
  for (double time : times)
    raster.render(camera_at(scene, time), {.renderer = renderer_named("raster")}, false);
  EXPECT_EQ(raster.compilations(), 1);
}

TEST(RenderSession, TheTracersIntegratorsShareOneCompilation) {
  const Scene scene = load_scene("cornell-box");
  RenderSession session(scene);
  const Camera camera = camera_at(scene, 0);
  for (const char* name : {"path", "whitted", "direct"}) {
    const FrameSettings settings{.renderer = renderer_named(name), .samples_per_pixel = 1};
    EXPECT_TRUE(same_bits(session.render(camera, settings, false).finished(),
                          render_frame(scene, camera, settings, false).finished()))
        << name;
  }
  // Ground truth of a still scene reuses it too, and equals a lone ground-truth render.
  const GroundTruthTimes times = default_ground_truth_times(camera);
  const GroundTruthBuffer kept = session.ground_truth(camera, {}, times);
  EXPECT_EQ(session.compilations(), 1);
  EXPECT_TRUE(same_bits(kept.image(), render_ground_truth_frame(scene, camera, {}, times).image()));
}

}  // namespace
}  // namespace obscura
