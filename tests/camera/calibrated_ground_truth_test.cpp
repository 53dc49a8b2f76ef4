// Ground truth through a calibrated lens: for every pixel of a moving camera with an off-centre
// principal point, OpenCV distortion and a rolling shutter, the forward flow must take the seen
// point (the P channel) to where the camera projects it in the second exposure, on the line
// that sees it then — checked against Camera::project, the lens model's forward map, which the
// flow's rays (the inverse map) do not use.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "obscura/camera/calibrated_projection.h"
#include "obscura/camera/frames.h"
#include "obscura/scene/builtin_scenes.h"
#include "obscura/scene/surface_motion.h"
#include "obscura/trace/ground_truth_render.h"
#include "obscura/trace/trace_scene.h"

namespace obscura {
namespace {

void expect_flow_reprojects(double line_time_s) {
  Scene scene = make_cornell_box();
  Camera& c = scene.camera;
  c.projection = CalibratedProjection{
      .k = {.fx = 70, .fy = 72, .cx = 37.3, .cy = 26.1, .skew = 0.4},
      .lens = PinholeDistortion{.k1 = -0.3, .k2 = 0.1, .p1 = 0.002, .p2 = -0.003}};
  c.film.width_px = 64;
  c.film.height_px = 48;
  Point3d eye(0.278, 0.273, -0.8);
  c.world_from_camera =
      AnimatedTransform({{0, world_from_camera_look_at(eye, eye + Vector3d(0, 0, 1))},
                         {1, world_from_camera_look_at(eye + Vector3d(0.06, 0.02, 0.05),
                                                       eye + Vector3d(0.03, 0, 1))}});
  c.shutter = {.open_s = 0, .close_s = 0.2, .line_time_s = line_time_s};
  c.validate();
  TraceSceneOptions options;
  options.shutter = Shutter{.open_s = 0, .close_s = 1};
  TraceScene trace(scene, std::make_shared<EmbreeDevice>(), options);
  GroundTruthBuffer gt = render_ground_truth(trace, SurfaceMotion(scene), c, {0, 0.2});
  int checked = 0;
  double worst = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      float fx = gt.value(x, y, "flow.forward.X"), fy = gt.value(x, y, "flow.forward.Y");
      if (std::isnan(fx)) continue;
      Point3d p(gt.value(x, y, "P.X"), gt.value(x, y, "P.Y"), gt.value(x, y, "P.Z"));
      Point2d q(x + 0.5 + fx, y + 0.5 + fy);
      // The second exposure sees q's line at 0.2 s + its delay (0 for a global shutter).
      double t = 0.2 + std::max(0.0, q.y - 0.5) * line_time_s;
      auto at = c.project(p, t);
      ASSERT_TRUE(at) << x << ", " << y;
      worst = std::max(worst, std::hypot(at->film_point.x - q.x, at->film_point.y - q.y));
      ++checked;
    }
  EXPECT_LE(worst, 0.01);
  EXPECT_GT(checked, 64 * 48 / 2);
}

TEST(CalibratedGroundTruth, FlowReprojectsThroughADistortedOffCentreLens) {
  expect_flow_reprojects(0);
}

TEST(CalibratedGroundTruth, FlowReprojectsThroughADistortedLensWithARollingShutter) {
  expect_flow_reprojects(1.0 / 480);
}

}  // namespace
}  // namespace obscura
