#include "obscura/io/gltf_camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

Camera from_gltf_perspective(const GltfPerspective& g, int width_px, int height_px) {
  if (!(g.yfov_radians > 0 && g.yfov_radians < std::numbers::pi))
    throw Error("camera.perspective.yfov",
                "must be in (0, π) radians; got " + number_text(g.yfov_radians));
  if (g.aspect_ratio && !(*g.aspect_ratio > 0))
    throw Error("camera.perspective.aspectRatio",
                "must be positive; got " + number_text(*g.aspect_ratio));
  Camera camera;
  camera.projection =
      Perspective::from_vertical_fov_degrees(g.yfov_radians * 180 / std::numbers::pi);
  camera.near_m = g.znear_m;
  camera.far_m = g.zfar_m ? *g.zfar_m : std::numeric_limits<double>::infinity();
  camera.film.width_px = width_px;
  camera.film.height_px =
      g.aspect_ratio ? std::max(1, int(std::lround(width_px / *g.aspect_ratio))) : height_px;
  camera.validate();
  return camera;
}

Camera from_gltf_orthographic(const GltfOrthographic& g, int width_px) {
  if (!(g.xmag_m > 0))
    throw Error("camera.orthographic.xmag", "must be positive; got " + number_text(g.xmag_m));
  if (!(g.ymag_m > 0))
    throw Error("camera.orthographic.ymag", "must be positive; got " + number_text(g.ymag_m));
  Camera camera;
  camera.projection = Orthographic{.view_height_m = 2 * g.ymag_m, .view_width_m = 2 * g.xmag_m};
  camera.near_m = g.znear_m;
  camera.far_m = g.zfar_m;
  camera.film.width_px = width_px;
  camera.film.height_px = std::max(1, int(std::lround(width_px * g.ymag_m / g.xmag_m)));
  camera.validate();
  return camera;
}

GltfCamera to_gltf(const Camera& camera) {
  GltfCamera g;
  if (std::holds_alternative<Perspective>(camera.projection)) {
    ScreenWindow w = camera.screen_window();
    GltfPerspective p;
    p.yfov_radians = std::atan(w.y_max) - std::atan(w.y_min);
    p.aspect_ratio = camera.film.image_aspect();
    p.znear_m = camera.near_m;
    if (!std::isinf(camera.far_m)) p.zfar_m = camera.far_m;
    g.perspective = p;
  } else if (std::holds_alternative<Orthographic>(camera.projection)) {
    ScreenWindow w = camera.screen_window();
    g.orthographic = GltfOrthographic{.xmag_m = 0.5 * (w.x_max - w.x_min),
                                      .ymag_m = 0.5 * (w.y_max - w.y_min),
                                      .znear_m = camera.near_m,
                                      .zfar_m = camera.far_m};
  } else {
    throw Error("camera",
                "glTF has no " + std::string(projection_name(camera.projection)) + " cameras");
  }
  return g;
}

BlenderCamera to_blender(const Camera& camera) {
  BlenderCamera b;
  b.clip_start_m = camera.near_m;
  b.clip_end_m = camera.far_m;
  b.use_dof = camera.lens.depth_of_field;
  b.fstop = camera.f_number();
  b.focus_distance_m = camera.lens.focus_distance_m;
  b.aperture_blades = camera.lens.aperture.blades;
  b.aperture_rotation_degrees = camera.lens.aperture.rotation_degrees;
  std::visit(Overloaded{
                 [&](const Perspective& p) {
                   b.lens_mm = p.focal_length_mm;
                   b.sensor_width_mm = p.sensor_width_mm;
                   b.sensor_height_mm = p.sensor_height_mm;
                   b.sensor_fit = p.sensor_fit == SensorFit::horizontal ? "HORIZONTAL"
                                  : p.sensor_fit == SensorFit::vertical ? "VERTICAL"
                                                                        : "AUTO";
                   b.shift_x = p.lens_shift.x;
                   b.shift_y = p.lens_shift.y;
                 },
                 [&](const Orthographic&) {
                   ScreenWindow w = camera.screen_window();
                   b.type = "ORTHO";
                   b.ortho_scale = std::max(w.x_max - w.x_min, w.y_max - w.y_min);
                 },
                 [&](const Equirectangular&) {
                   b.type = "PANO";
                   b.panorama_type = "EQUIRECTANGULAR";
                 },
                 [&](const Fisheye& f) {
                   b.type = "PANO";
                   b.panorama_type = "FISHEYE_EQUIDISTANT";
                   b.fisheye_fov_degrees = f.fov_degrees;
                 },
                 // Blender's cameras have no lens distortion and no K with skew.
                 [&](const CalibratedProjection&) { b.type = "NONE"; },
                 // Nor real lens prescriptions.
                 [&](const LensSystemProjection&) { b.type = "NONE"; },
             },
             camera.projection);
  return b;
}

}  // namespace obscura
