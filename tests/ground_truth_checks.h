// Checks of a GroundTruthBuffer of ground_truth_scene(true) against its analytic answers, for
// either renderer: forward flow is the P channel (the square's points slid with it) reprojected
// by hand through the camera at close; backward flow the ray at close met by hand and projected
// back by hand through the camera at open.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ground_truth_test_scene.h"
#include "obscura/film/ground_truth_buffer.h"

namespace obscura::testing {

using S = GroundTruthScene;

inline Point2d centre_of(int x, int y) {
  return {x + 0.5, y + 0.5};
}

inline constexpr double kEdgeMargin = 1e-3;  // m: pixels whose ray passes this close to an edge

// Checks every pixel's depth, range, position, normals, ids and time against the analytic scene
// (camera moving); returns how many pixels see the square.
inline int expect_surfaces_match_analytic_scene(const GroundTruthBuffer& gt) {
  const AnalyticCamera camera{.moves = true};
  int square_pixels = 0;
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      const Point2d p = centre_of(x, y);
      const AnalyticHit hit = analytic_hit(camera, p.x, p.y, S::kOpen);
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
  return square_pixels;
}

struct FlowCheck {
  int forward = 0, backward = 0, off_film = 0;  // pixels checked
  double worst_px = 0;                          // the largest forward error
};

inline FlowCheck expect_flow_matches_analytic_scene(const GroundTruthBuffer& gt) {
  const AnalyticCamera camera{.moves = true};
  int forward_checked = 0, backward_checked = 0, off_film = 0;
  double worst = 0;
  for (int y = 0; y < S::kHeight; ++y)
    for (int x = 0; x < S::kWidth; ++x) {
      SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
      const Point2d p = centre_of(x, y);
      const AnalyticHit first = analytic_hit(camera, p.x, p.y, S::kOpen);
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
      const AnalyticHit second = analytic_hit(camera, p.x, p.y, S::kClose);
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
  return {forward_checked, backward_checked, off_film, worst};
}

}  // namespace obscura::testing
