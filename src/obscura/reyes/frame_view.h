// The camera as REYES uses it for one frame: camera space at the two ends of the exposure (every
// surface point moves linearly between them), the pinhole projection to raster space, and the
// thin lens's displacement of a point's image for a lens point. These are the inverse of the
// camera's own rays (camera/camera.h: every lens point aims at the point of the focus plane the
// pinhole ray reaches), so a point lands where the tracer's ray through that film point and lens
// point would find it.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"

namespace obscura::reyes {

struct RasterBounds {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double x, double y) {
    x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1;
    y0 = y < y0 ? y : y0, y1 = y > y1 ? y : y1;
  }
  void grow(double by) { x0 -= by, y0 -= by, x1 += by, y1 += by; }
  bool empty() const { return !(x0 <= x1 && y0 <= y1); }
  bool overlaps(const RasterBounds& b) const {
    return x0 <= b.x1 && b.x0 <= x1 && y0 <= b.y1 && b.y0 <= y1;
  }
};

class FrameView {
 public:
  // Throws obscura::Error for projections REYES does not draw (spherical, calibrated, lens
  // systems): only perspective (with the thin lens) and orthographic cameras.
  FrameView(const Camera& camera, bool scene_moves);

  bool perspective() const { return perspective_; }
  bool moves() const { return moves_; }  // anything (camera included) moves
  bool defocused() const { return lens_radius_m_ > 0; }
  double lens_radius_m() const { return lens_radius_m_; }
  double open_s() const { return t0_; }  // the exposure interval (rolling shutter in)
  double close_s() const { return t1_; }
  double shading_time_s() const { return shade_s_; }
  double near_m() const { return near_m_; }
  double far_m() const { return far_m_; }
  // The fraction of the exposure interval at `time_s` (0 when nothing moves).
  double motion_fraction(double time_s) const {
    return t1_ > t0_ ? (time_s - t0_) / (t1_ - t0_) : 0;
  }

  const Transform& camera_from_world_open() const { return camera_from_world0_; }
  const Transform& camera_from_world_close() const { return camera_from_world1_; }
  // The eye (perspective) at the shading time, or the direction towards the viewer.
  Point3d eye() const { return eye_; }
  Vector3d to_viewer() const { return to_viewer_; }

  // Depth along the optical axis of a camera-space point.
  static double depth(Point3d p) { return -p.z; }
  // Raster position of camera-space `p` through the lens centre (perspective: depth > 0).
  Point2d project(Point3d p) const {
    const double wx = perspective_ ? p.x / -p.z : p.x, wy = perspective_ ? p.y / -p.z : p.y;
    return {ax_ * wx + bx_, ay_ * wy + by_};
  }
  // The image's shift (raster pixels) for lens offset `lens_m` (metres on the lens, from
  // lens_offset) at depth `depth_m`: the thin lens's (1/S_f − 1/S) · lens point, scaled.
  Point2d lens_shift(Point2d lens_m, double depth_m) const {
    const double k = inv_focus_ - 1 / depth_m;
    return {ax_ * lens_m.x * k, ay_ * lens_m.y * k};
  }
  // The thin lens's factor 1/S_f − 1/S at depth S (increasing with S), and the raster scales
  // that turn a lens point times it into a shift: shift = (ax · l.x · k, ay · l.y · k).
  double lens_factor(double depth_m) const { return inv_focus_ - 1 / depth_m; }
  double raster_scale_x() const { return ax_; }
  double raster_scale_y() const { return ay_; }
  // The lens point (metres, camera-space x and y) of a lens sample u ∈ [0,1)², as the camera
  // draws its rays.
  Point2d lens_offset(Point2f u) const;
  // The largest |shift| in pixels for any lens point over depths [d0, d1].
  double max_lens_shift_px(double d0, double d1) const;
  // Pixels per window unit (for culling margins).
  double pixels_per_window_unit() const { return ax_ > -ay_ ? ax_ : -ay_; }
  // The window rectangle of the raster rectangle [−margin, width + margin] × [−margin, height +
  // margin] (perspective: tangents; orthographic: metres).
  void window_bounds(double margin_px, double& x0, double& x1, double& y0, double& y1) const;

 private:
  const Camera* camera_;
  bool perspective_ = true, moves_ = false;
  double t0_ = 0, t1_ = 0, shade_s_ = 0, near_m_ = 0, far_m_ = 0;
  Transform camera_from_world0_, camera_from_world1_;
  Point3d eye_;
  Vector3d to_viewer_;
  double width_px_ = 0, height_px_ = 0;
  double ax_ = 1, bx_ = 0, ay_ = 1, by_ = 0;  // raster = a · window + b
  double lens_radius_m_ = 0, inv_focus_ = 0;
};

}  // namespace obscura::reyes
