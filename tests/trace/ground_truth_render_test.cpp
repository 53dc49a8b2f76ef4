// The tracer's ground truth against the analytic answers of a wall and a sliding square seen by
// a moving, shifted perspective camera (ground_truth_test_scene.h).
#include "obscura/trace/ground_truth_render.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ground_truth_checks.h"
#include "obscura/math/error.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

using S = testing::GroundTruthScene;

GroundTruthBuffer render(const Scene& scene, std::optional<GroundTruthTimes> times = {}) {
  TraceScene trace(scene, testing::embree_device());
  SurfaceMotion motion(scene);
  return render_ground_truth(trace, motion, scene.camera,
                             times.value_or(default_ground_truth_times(scene.camera)));
}

TEST(GroundTruthRender, DepthPositionNormalsAndIdsMatchTheAnalyticScene) {
  const GroundTruthBuffer gt = render(testing::ground_truth_scene(true));
  EXPECT_GT(testing::expect_surfaces_match_analytic_scene(gt), 20);  // the square is in view
}

TEST(GroundTruthRender, FlowIsTheAnalyticReprojectionThroughTheMovingCamera) {
  const GroundTruthBuffer gt = render(testing::ground_truth_scene(true));
  const testing::FlowCheck check = testing::expect_flow_matches_analytic_scene(gt);
  EXPECT_GT(check.forward, S::kWidth * S::kHeight / 2);
  EXPECT_GT(check.backward, S::kWidth * S::kHeight / 2);
  EXPECT_GT(check.off_film, 0);  // the camera's turn takes some points off the film
  std::printf("tracer forward flow: %d pixels, worst error %.2e px\n", check.forward,
              check.worst_px);
}

TEST(GroundTruthRender, AnAnimatedObjectsFlowIsItsProjectedTravel) {
  const Scene scene = testing::ground_truth_scene(false);  // only the square moves
  const GroundTruthBuffer gt = render(scene);
  const double travel_px = S::fx() * (S::kSquareX1 - S::kSquareX0) / -S::kSquareZ;
  int square = 0;
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      const float instance = gt.value(x, y, "instance");
      const double expected = instance == 1.f ? travel_px : 0.0;
      EXPECT_NEAR(gt.value(x, y, "flow.forward.X"), expected, 1e-3);
      EXPECT_NEAR(gt.value(x, y, "flow.forward.Y"), 0, 1e-3);
      square += instance == 1.f;
    }
  EXPECT_GT(square, 20);
}

TEST(GroundTruthRender, APointOnADeformingMeshMovesWithItsTriangle) {
  const GroundTruthBuffer gt = render(testing::stretching_square_scene());
  int square = 0;
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      if (gt.value(x, y, "instance") != 1.f) continue;
      const double px = gt.value(x, y, "P.X");
      const double expected = S::fx() * (testing::stretched_x(px) - px) / -S::kSquareZ;
      EXPECT_NEAR(gt.value(x, y, "flow.forward.X"), expected, 1e-3);
      EXPECT_NEAR(gt.value(x, y, "flow.forward.Y"), 0, 1e-3);
      ++square;
    }
  EXPECT_GT(square, 20);
}

TEST(GroundTruthRender, FlowTimesChooseTheInterval) {
  const Scene scene = testing::ground_truth_scene(false);
  // Half the shutter, and backwards in time: the flow is half the travel, reversed.
  const double half = (S::kOpen + S::kClose) / 2;
  const GroundTruthBuffer gt = render(scene, GroundTruthTimes{half, S::kOpen});
  const double travel_px = S::fx() * (S::kSquareX1 - S::kSquareX0) / -S::kSquareZ;
  int square = 0;
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      EXPECT_EQ(gt.value(x, y, "time"), float(half));
      if (gt.value(x, y, "instance") != 1.f) continue;
      EXPECT_NEAR(gt.value(x, y, "flow.forward.X"), -travel_px / 2, 1e-3);
      ++square;
    }
  EXPECT_GT(square, 20);
}

TEST(GroundTruthRender, MissesAreMarked) {
  Scene scene = testing::ground_truth_scene(false);
  scene.camera.world_from_camera = Transform::rotate_y(std::numbers::pi);  // facing away
  const GroundTruthBuffer gt = render(scene);
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      EXPECT_TRUE(std::isinf(gt.value(x, y, "Z")));
      EXPECT_TRUE(std::isinf(gt.value(x, y, "range")));
      EXPECT_TRUE(std::isnan(gt.value(x, y, "P.X")));
      EXPECT_TRUE(std::isnan(gt.value(x, y, "N.Y")));
      EXPECT_EQ(gt.value(x, y, "instance"), -1.f);
      EXPECT_EQ(gt.value(x, y, "material"), -1.f);
      EXPECT_TRUE(std::isnan(gt.value(x, y, "flow.forward.X")));
      EXPECT_TRUE(std::isnan(gt.value(x, y, "flow.backward.Y")));
    }
}

TEST(GroundTruthRender, CropCoversTheCropWindowsPixels) {
  Scene full_scene = testing::ground_truth_scene(true);
  Scene crop_scene = full_scene;
  crop_scene.camera.film.crop = {.x_min = 0.25, .y_min = 0.5, .x_max = 0.75, .y_max = 1};
  const GroundTruthBuffer full = render(full_scene), crop = render(crop_scene);
  const Bounds2i window = crop_scene.camera.film.crop_pixels();
  ASSERT_EQ(crop.width(), window.width());
  ASSERT_EQ(crop.height(), window.height());
  for (int y = 0; y < crop.height(); ++y)
    for (int x = 0; x < crop.width(); ++x)
      for (const char* c : kGroundTruthChannels) {
        const float a = crop.value(x, y, c), b = full.value(x + window.min.x, y + window.min.y, c);
        if (std::isnan(b))
          EXPECT_TRUE(std::isnan(a));
        else
          EXPECT_EQ(a, b) << c;
      }
}

TEST(GroundTruthRender, TimesOutsideTheCompiledMotionAreRefused) {
  const Scene scene = testing::ground_truth_scene(false);
  TraceScene trace(scene, testing::embree_device());
  SurfaceMotion motion(scene);
  EXPECT_THROW(render_ground_truth(trace, motion, scene.camera, {0, 1}), Error);
}

}  // namespace
}  // namespace obscura
