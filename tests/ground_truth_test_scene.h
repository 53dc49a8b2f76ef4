// The scene of the ground-truth tests, for both renderers, with its analytic answers: a wall
// facing the camera 5 m away and a 0.8 m square 3 m away that slides along +X, seen by a
// perspective camera with lens shift (an off-centre principal point) that moves and turns.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "obscura/camera/camera.h"
#include "obscura/math/vector.h"
#include "obscura/scene/scene.h"

namespace obscura::testing {

struct GroundTruthScene {
  static constexpr int kWidth = 48, kHeight = 32;
  static constexpr double kFocalMm = 35, kSensorMm = 36;
  static constexpr double kShiftX = 0.1, kShiftY = 0.05;
  static constexpr double kOpen = 0, kClose = 0.01;
  static constexpr double kWallZ = -5, kSquareZ = -3, kHalfSide = 0.4;
  static constexpr double kSquareX0 = -0.3, kSquareX1 = -0.1;  // its centre at open and close
  // The camera at close: moved by (0.2, 0.1, 0.3) m and turned 3° about +Y (at open: identity).
  static constexpr double kTurnDegrees = 3;
  static constexpr double kMoveX = 0.2, kMoveY = 0.1, kMoveZ = 0.3;

  // Pixels: fx = f·W / sensor width (horizontal fit); lens shift slides the window by
  // shift × the fitted width (W pixels): right and up, so the principal point moves left and down.
  static constexpr double fx() { return kFocalMm * kWidth / kSensorMm; }
  static constexpr double cx() { return kWidth / 2.0 - kShiftX * kWidth; }   // raster
  static constexpr double cy() { return kHeight / 2.0 + kShiftY * kWidth; }  // raster

  // The square's centre x at time t (linear between the keys, held outside).
  static double square_x(double t) {
    double u = std::clamp((t - kOpen) / (kClose - kOpen), 0.0, 1.0);
    return kSquareX0 + (kSquareX1 - kSquareX0) * u;
  }
};

inline Scene ground_truth_scene(bool camera_moves) {
  using S = GroundTruthScene;
  Scene scene;
  scene.name = "ground truth";
  scene.materials = {diffuse_material("wall", Rgb(0.5f)), diffuse_material("square", Rgb(0.8f))};
  Mesh wall;
  wall.name = "wall";
  const float w = 40, z = float(S::kWallZ);
  wall.positions = {{-w, -w, z}, {w, -w, z}, {w, w, z}, {-w, w, z}};
  wall.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from +Z: facing the camera
  wall.material = 0;
  scene.add_mesh(std::move(wall));
  Mesh square;
  square.name = "square";
  const float h = float(S::kHalfSide);
  square.positions = {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}};
  square.indices = {0, 1, 2, 0, 2, 3};
  square.material = 1;
  scene.add_mesh(std::move(square), Transform::translate({S::kSquareX0, 0, S::kSquareZ}));
  scene.instances[1].motion = {{S::kOpen, Transform::translate({S::kSquareX0, 0, S::kSquareZ})},
                               {S::kClose, Transform::translate({S::kSquareX1, 0, S::kSquareZ})}};

  Camera& camera = scene.camera;
  Perspective lens;
  lens.focal_length_mm = S::kFocalMm;
  lens.sensor_width_mm = S::kSensorMm;
  lens.sensor_fit = SensorFit::horizontal;
  lens.lens_shift = {S::kShiftX, S::kShiftY};
  camera.projection = lens;
  camera.film.width_px = S::kWidth;
  camera.film.height_px = S::kHeight;
  camera.shutter = {.open_s = S::kOpen, .close_s = S::kClose};
  if (camera_moves)
    camera.world_from_camera = AnimatedTransform(
        {{S::kOpen, Transform()},
         {S::kClose, Transform::translate({S::kMoveX, S::kMoveY, S::kMoveZ}) *
                         Transform::rotate_y(S::kTurnDegrees * std::numbers::pi / 180)}});
  return scene;
}

// A square 3 m in front of a still camera whose right edge stretches from x = 0.4 to 0.6 m over
// the shutter while its left edge stays at −0.4 (a deforming mesh, two time steps): a material
// point at x moves to −0.4 + (x + 0.4) · 1.0 / 0.8.
inline Scene stretching_square_scene() {
  Scene scene = ground_truth_scene(false);
  Mesh& square = scene.meshes[1];
  const float h = float(GroundTruthScene::kHalfSide);
  std::vector<Point3f> stretched = square.positions;
  stretched[1].x = stretched[2].x = h + 0.2f;
  square.deformation.open_s = GroundTruthScene::kOpen;
  square.deformation.close_s = GroundTruthScene::kClose;
  square.deformation.positions = {square.positions, stretched};
  scene.instances[1].motion.clear();
  scene.instances[1].world_from_object = Transform::translate({0, 0, GroundTruthScene::kSquareZ});
  return scene;
}

inline double stretched_x(double x) {
  const double h = GroundTruthScene::kHalfSide;
  return -h + (x + h) * (2 * h + 0.2) / (2 * h);
}

// The analytic camera: where the camera (at open: identity; at close: moved and turned when it
// moves) is and which way a raster point's ray goes, written out by hand.
struct AnalyticCamera {
  bool moves = true;

  Point3d centre(double t) const {
    using S = GroundTruthScene;
    return t >= S::kClose && moves ? Point3d(S::kMoveX, S::kMoveY, S::kMoveZ) : Point3d(0, 0, 0);
  }
  double turn(double t) const {
    using S = GroundTruthScene;
    return t >= S::kClose && moves ? S::kTurnDegrees * std::numbers::pi / 180 : 0;
  }
  // World direction (not unit) of the ray through raster (u, v) at time t: the camera-space
  // direction ((u − cx)/fx, −(v − cy)/fx, −1) turned about +Y.
  Vector3d direction(double u, double v, double t) const {
    using S = GroundTruthScene;
    Vector3d d((u - S::cx()) / S::fx(), -(v - S::cy()) / S::fx(), -1);
    const double a = turn(t), c = std::cos(a), s = std::sin(a);
    return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
  }
  // Raster point of world point p at time t, or nothing behind the camera.
  std::optional<Point2d> project(Point3d p, double t) const {
    using S = GroundTruthScene;
    const Vector3d r = p - centre(t);
    const double a = -turn(t), c = std::cos(a), s = std::sin(a);  // undo the turn
    const Vector3d q(c * r.x + s * r.z, r.y, -s * r.x + c * r.z);
    if (q.z >= 0) return std::nullopt;
    return Point2d(S::cx() + S::fx() * q.x / -q.z, S::cy() - S::fx() * q.y / -q.z);
  }
};

// What the ray through raster (u, v) at time t meets first: the square (at its place at t) or
// the wall, by hand. `on_square` tells which; `edge_distance` is how far (m, in the square's
// plane) the ray passes from the square's edge, to skip pixels a rounding could change.
struct AnalyticHit {
  Point3d position;
  bool on_square = false;
  double edge_distance = 0;
};

inline AnalyticHit analytic_hit(const AnalyticCamera& camera, double u, double v, double t) {
  using S = GroundTruthScene;
  const Point3d o = camera.centre(t);
  const Vector3d d = camera.direction(u, v, t);
  const Point3d on_square = o + d * ((S::kSquareZ - o.z) / d.z);
  const double ex = std::abs(on_square.x - S::square_x(t)) - S::kHalfSide;
  const double ey = std::abs(on_square.y) - S::kHalfSide;
  const double edge = std::max(ex, ey);
  if (edge < 0) return {on_square, true, std::min(-ex, -ey)};
  return {o + d * ((S::kWallZ - o.z) / d.z), false, edge};
}

}  // namespace obscura::testing
