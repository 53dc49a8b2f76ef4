// REYES's ground truth against the analytic scene the tracer's and the rasterizer's are held to
// (ground_truth_checks.h): visibility from REYES's own hider at the pixel centres, values from
// the pixel-centre ray met with the triangle it saw.
#include "obscura/reyes/ground_truth.h"

#include <gtest/gtest.h>

#include "ground_truth_checks.h"
#include "obscura/math/error.h"

namespace obscura::reyes {
namespace {

using S = testing::GroundTruthScene;

GroundTruthBuffer render(const Scene& scene) {
  const ReyesScene compiled(scene);
  return render_ground_truth(compiled, scene.camera, {}, default_ground_truth_times(scene.camera),
                             nullptr);
}

TEST(ReyesGroundTruth, DepthPositionNormalsAndIdsMatchTheAnalyticScene) {
  const GroundTruthBuffer gt = render(testing::ground_truth_scene(true));
  EXPECT_GT(testing::expect_surfaces_match_analytic_scene(gt), 20);
}

TEST(ReyesGroundTruth, FlowIsTheAnalyticReprojectionThroughTheMovingCamera) {
  const GroundTruthBuffer gt = render(testing::ground_truth_scene(true));
  const testing::FlowCheck check = testing::expect_flow_matches_analytic_scene(gt);
  EXPECT_GT(check.forward, S::kWidth * S::kHeight / 2);
  EXPECT_GT(check.backward, S::kWidth * S::kHeight / 2);
  EXPECT_GT(check.off_film, 0);
}

TEST(ReyesGroundTruth, AnAnimatedObjectsFlowIsItsProjectedTravel) {
  const GroundTruthBuffer gt = render(testing::ground_truth_scene(false));
  const double travel_px = S::fx() * (S::kSquareX1 - S::kSquareX0) / -S::kSquareZ;
  int square = 0;
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      const bool on_square = gt.value(x, y, "instance") == 1.f;
      EXPECT_NEAR(gt.value(x, y, "flow.forward.X"), on_square ? travel_px : 0.0, 1e-3);
      EXPECT_NEAR(gt.value(x, y, "flow.forward.Y"), 0, 1e-3);
      square += on_square;
    }
  EXPECT_GT(square, 20);
}

TEST(ReyesGroundTruth, RefusesARollingShutter) {
  Scene scene = testing::ground_truth_scene(false);
  scene.camera.shutter.line_time_s = 1e-5;
  EXPECT_THROW(render(scene), Error);
}

}  // namespace
}  // namespace obscura::reyes
