// A cancel reaches inside the ground truth and the glare's PSF, not only before and after them:
// with the flag already set, neither renderer's ground truth looks at a pixel (every pixel stays
// a miss, where without it the Cornell box is seen) and the colour PSF is not built; unset, the
// same calls see the box and build the PSF.
#include <gtest/gtest.h>

#include <atomic>

#include "obscura/film/diffraction_psf.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/io/scene_loader.h"
#include "obscura/render/ground_truth_frame.h"
#include "obscura/render/renderer.h"

namespace obscura {
namespace {

int pixels_that_hit(const GroundTruthBuffer& buffer) {
  int hits = 0;
  for (int y = 0; y < buffer.height(); ++y)
    for (int x = 0; x < buffer.width(); ++x) hits += buffer.value(x, y, "instance") >= 0;
  return hits;
}

TEST(GroundTruthCancel, ASetCancelStopsBothRenderersBeforeAnyPixel) {
  const Scene scene = load_scene("cornell-box");
  Camera camera = scene.camera;
  camera.film.width_px = 48;
  camera.film.height_px = 32;
  const GroundTruthTimes times = default_ground_truth_times(camera);
  for (const char* name : {"path", "raster"}) {
    FrameSettings settings{.renderer = renderer_named(name)};
    EXPECT_GT(pixels_that_hit(render_ground_truth_frame(scene, camera, settings, times)), 0)
        << name;
    const std::atomic<bool> cancel{true};
    settings.cancel = &cancel;
    EXPECT_EQ(pixels_that_hit(render_ground_truth_frame(scene, camera, settings, times)), 0)
        << name;
  }
}

TEST(GroundTruthCancel, ASetCancelStopsTheColourPsf) {
  const DiffractionOptics optics{.pupil = [](double x, double y) { return x * x + y * y <= 1; },
                                 .f_number = 8,
                                 .pixel_width_mm = 0.005,
                                 .pixel_height_mm = 0.005};
  EXPECT_EQ(rgb_psf(optics, 16).width, 33);
  const std::atomic<bool> cancel{true};
  EXPECT_TRUE(rgb_psf(optics, 16, &cancel).data.empty());
}

}  // namespace
}  // namespace obscura
