// The rasterizer's ground truth against the same analytic scene as the tracer's
// (ground_truth_checks.h): visibility from the rasterizer, values from the pixel-centre ray met
// with the drawn triangle, so the same 0.01 px flow bound holds.
#include "obscura/raster/ground_truth_render.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ground_truth_checks.h"
#include "obscura/math/error.h"

namespace obscura::raster {
namespace {

using S = testing::GroundTruthScene;

RasterSettings settings(bool aovs, int msaa_samples = 1) {
  RasterSettings s;
  s.aovs = aovs;
  s.msaa_samples = msaa_samples;
  return s;
}

GroundTruthBuffer render(const Scene& scene, RasterSettings settings = raster::settings(true)) {
  SceneRasterizer rasterizer(scene, settings);
  SurfaceMotion motion(scene);
  return render_ground_truth(rasterizer, motion, scene.camera,
                             default_ground_truth_times(scene.camera));
}

TEST(RasterGroundTruth, DepthPositionNormalsAndIdsMatchTheAnalyticScene) {
  const GroundTruthBuffer gt = render(testing::ground_truth_scene(true));
  EXPECT_GT(testing::expect_surfaces_match_analytic_scene(gt), 20);
}

TEST(RasterGroundTruth, FlowIsTheAnalyticReprojectionThroughTheMovingCamera) {
  const GroundTruthBuffer gt = render(testing::ground_truth_scene(true));
  const testing::FlowCheck check = testing::expect_flow_matches_analytic_scene(gt);
  EXPECT_GT(check.forward, S::kWidth * S::kHeight / 2);
  EXPECT_GT(check.backward, S::kWidth * S::kHeight / 2);
  EXPECT_GT(check.off_film, 0);
  std::printf("raster forward flow: %d pixels, worst error %.2e px\n", check.forward,
              check.worst_px);
}

TEST(RasterGroundTruth, AnAnimatedObjectsFlowIsItsProjectedTravel) {
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

TEST(RasterGroundTruth, APointOnADeformingMeshMovesWithItsTriangle) {
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

TEST(RasterGroundTruth, NeedsIdsAndOneSamplePerPixel) {
  const Scene scene = testing::ground_truth_scene(false);
  EXPECT_THROW(render(scene, settings(false)), Error);
  EXPECT_THROW(render(scene, settings(true, 4)), Error);
}

}  // namespace
}  // namespace obscura::raster
