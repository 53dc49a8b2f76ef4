#include "obscura/reyes/frame_view.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "obscura/camera/aperture.h"
#include "obscura/math/error.h"

namespace obscura::reyes {

FrameView::FrameView(const Camera& camera, bool scene_moves) : camera_(&camera) {
  camera.validate();
  if (std::holds_alternative<Perspective>(camera.projection))
    perspective_ = true;
  else if (std::holds_alternative<Orthographic>(camera.projection))
    perspective_ = false;
  else
    throw Error("reyes", "draws perspective and orthographic cameras only (the camera '" +
                             camera.name + "' has another projection): use the tracer");
  const Shutter exposed = camera.exposure_interval();
  // Motion blurs only over an exposure of some length (a zero-length shutter is a still).
  moves_ =
      (scene_moves || camera.world_from_camera.is_animated()) && exposed.close_s > exposed.open_s;
  // Shading happens once, at the moment a still frame would show (camera_sample.h's still time).
  shade_s_ = camera.shutter.time_at(0.5);
  t0_ = moves_ ? exposed.open_s : shade_s_;
  t1_ = moves_ ? exposed.close_s : shade_s_;
  near_m_ = camera.near_m;
  far_m_ = camera.far_m;
  const Transform world0 = camera.world_from_camera.at(t0_);
  camera_from_world0_ = inverse(world0);
  camera_from_world1_ = inverse(camera.world_from_camera.at(t1_));
  const Transform shade = camera.world_from_camera.at(shade_s_);
  eye_ = shade(Point3d(0, 0, 0));
  const Vector3d back = shade(Vector3d(0, 0, 1));
  to_viewer_ = back / length(back);
  width_px_ = camera.film.width_px;
  height_px_ = camera.film.height_px;
  const ScreenWindow w = camera.screen_window();
  ax_ = camera.film.width_px / (w.x_max - w.x_min);
  bx_ = -w.x_min * ax_;
  ay_ = -camera.film.height_px / (w.y_max - w.y_min);
  by_ = w.y_max * camera.film.height_px / (w.y_max - w.y_min);
  if (perspective_ && camera.lens.depth_of_field) {
    lens_radius_m_ = camera.lens_radius_m();
    inv_focus_ = 1 / camera.lens.focus_distance_m;
  }
}

Point2d FrameView::lens_offset(Point2f u) const {
  if (lens_radius_m_ <= 0) return {0, 0};
  const Point2d l = sample_aperture(camera_->lens.aperture, {u.x, u.y});
  return {lens_radius_m_ * l.x, lens_radius_m_ * l.y};
}

double FrameView::max_lens_shift_px(double d0, double d1) const {
  if (lens_radius_m_ <= 0) return 0;
  const double k = std::max(std::abs(inv_focus_ - 1 / d0), std::abs(inv_focus_ - 1 / d1));
  return lens_radius_m_ * k * std::max(std::abs(ax_), std::abs(ay_));
}

void FrameView::window_bounds(double margin_px, double& x0, double& x1, double& y0,
                              double& y1) const {
  x0 = (-margin_px - bx_) / ax_;
  x1 = (width_px_ + margin_px - bx_) / ax_;
  // ay < 0: raster y grows downwards.
  y1 = (-margin_px - by_) / ay_;
  y0 = (height_px_ + margin_px - by_) / ay_;
}

}  // namespace obscura::reyes
