// RenderSession: frames rendered through one session are the frames render_frame renders alone,
// bit for bit, while the tracer's scene is compiled once for a scene where nothing moves and
// again only when a moving scene's exposure changes.
#include "obscura/render/render_session.h"

#include <gtest/gtest.h>

#include <cstring>

#include "obscura/io/scene_loader.h"

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
  EXPECT_EQ(session.tracer_compilations(), 1);
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
  EXPECT_EQ(session.tracer_compilations(), 3);

  // The rasterizer compiles nothing the session keeps.
  RenderSession raster(scene);
  raster.render(camera_at(scene, 0), {.renderer = Renderer::kRaster}, false);
  EXPECT_EQ(raster.tracer_compilations(), 0);
}

}  // namespace
}  // namespace obscura
