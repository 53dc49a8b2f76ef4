// The tracer's ground truth against the analytic answers of a wall and a sliding square seen by
// a moving, shifted perspective camera (ground_truth_test_scene.h).
#include "obscura/trace/ground_truth_render.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ground_truth_test_scene.h"
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

Point2d centre_of(int x, int y) {
  return {x + 0.5, y + 0.5};
}

constexpr double kEdgeMargin = 1e-3;  // m: pixels whose ray passes this close to an edge

TEST(GroundTruthRender, DepthPositionNormalsAndIdsMatchTheAnalyticScene) {
  const Scene scene = testing::ground_truth_scene(true);
  const GroundTruthBuffer gt = render(scene);
  const testing::AnalyticCamera camera{.moves = true};
  int square_pixels = 0;
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      const Point2d p = centre_of(x, y);
      const testing::AnalyticHit hit = testing::analytic_hit(camera, p.x, p.y, S::kOpen);
      if (hit.edge_distance < kEdgeMargin) continue;
      SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
      const double plane_depth = hit.on_square ? -S::kSquareZ : -S::kWallZ;
      const Vector3d d = camera.direction(p.x, p.y, S::kOpen);  // camera at open: identity
      EXPECT_NEAR(gt.value(x, y, "Z"), plane_depth, 1e-5 * plane_depth);
      EXPECT_NEAR(gt.value(x, y, "range"), plane_depth * length(d), 1e-5 * plane_depth);
      EXPECT_NEAR(gt.value(x, y, "P.X"), hit.position.x, 1e-5);
      EXPECT_NEAR(gt.value(x, y, "P.Y"), hit.position.y, 1e-5);
      EXPECT_NEAR(gt.value(x, y, "P.Z"), hit.position.z, 1e-5);
      for (const char* n : {"N", "Ng"}) {
        const std::string name = n;
        EXPECT_NEAR(gt.value(x, y, name + ".X"), 0, 1e-6);
        EXPECT_NEAR(gt.value(x, y, name + ".Y"), 0, 1e-6);
        EXPECT_NEAR(gt.value(x, y, name + ".Z"), 1, 1e-6);
      }
      EXPECT_EQ(gt.value(x, y, "instance"), hit.on_square ? 1.f : 0.f);
      EXPECT_EQ(gt.value(x, y, "material"), hit.on_square ? 1.f : 0.f);
      EXPECT_EQ(gt.value(x, y, "time"), float(S::kOpen));
      square_pixels += hit.on_square;
    }
  EXPECT_GT(square_pixels, 20);  // the square is in view
}

// Forward flow: the P channel (the square's points slid with it) reprojected by hand through the
// camera at close; backward flow: the ray at close traced and projected back by hand.
TEST(GroundTruthRender, FlowIsTheAnalyticReprojectionThroughTheMovingCamera) {
  const Scene scene = testing::ground_truth_scene(true);
  const GroundTruthBuffer gt = render(scene);
  const testing::AnalyticCamera camera{.moves = true};
  int forward_checked = 0, backward_checked = 0, off_film = 0;
  double worst = 0;
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
      const Point2d p = centre_of(x, y);
      const testing::AnalyticHit first = testing::analytic_hit(camera, p.x, p.y, S::kOpen);
      if (first.edge_distance >= kEdgeMargin) {
        Point3d seen(gt.value(x, y, "P.X"), gt.value(x, y, "P.Y"), gt.value(x, y, "P.Z"));
        if (first.on_square) seen.x += S::kSquareX1 - S::kSquareX0;
        const Point2d then = *camera.project(seen, S::kClose);
        const bool on_film = then.x > 1e-3 && then.x < S::kWidth - 1e-3 && then.y > 1e-3 &&
                             then.y < S::kHeight - 1e-3;
        const bool border = std::min({std::abs(then.x), std::abs(then.x - S::kWidth),
                                      std::abs(then.y), std::abs(then.y - S::kHeight)}) < 1e-3;
        if (on_film) {
          EXPECT_NEAR(gt.value(x, y, "flow.forward.X"), then.x - p.x, 0.01);
          EXPECT_NEAR(gt.value(x, y, "flow.forward.Y"), then.y - p.y, 0.01);
          worst = std::max({worst, std::abs(gt.value(x, y, "flow.forward.X") - (then.x - p.x)),
                            std::abs(gt.value(x, y, "flow.forward.Y") - (then.y - p.y))});
          ++forward_checked;
        } else if (!border) {
          EXPECT_TRUE(std::isnan(gt.value(x, y, "flow.forward.X")));
          EXPECT_TRUE(std::isnan(gt.value(x, y, "flow.forward.Y")));
          ++off_film;
        }
      }
      const testing::AnalyticHit second = testing::analytic_hit(camera, p.x, p.y, S::kClose);
      if (second.edge_distance >= kEdgeMargin) {
        Point3d seen = second.position;
        if (second.on_square) seen.x -= S::kSquareX1 - S::kSquareX0;
        const Point2d then = *camera.project(seen, S::kOpen);
        if (then.x > 1e-3 && then.x < S::kWidth - 1e-3 && then.y > 1e-3 &&
            then.y < S::kHeight - 1e-3) {
          EXPECT_NEAR(gt.value(x, y, "flow.backward.X"), then.x - p.x, 0.01);
          EXPECT_NEAR(gt.value(x, y, "flow.backward.Y"), then.y - p.y, 0.01);
          ++backward_checked;
        }
      }
    }
  EXPECT_GT(forward_checked, S::kWidth * S::kHeight / 2);
  EXPECT_GT(backward_checked, S::kWidth * S::kHeight / 2);
  EXPECT_GT(off_film, 0);  // the camera's turn takes some points off the film
  std::printf("forward flow: %d pixels, worst error %.2e px\n", forward_checked, worst);
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
