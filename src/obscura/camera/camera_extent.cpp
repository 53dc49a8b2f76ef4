#include "obscura/camera/camera_extent.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "obscura/camera/camera.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"
#include "obscura/math/value_limits.h"

namespace obscura {

namespace {

bool within(double v, double limit) {
  return std::abs(v) <= limit;  // NaN: false
}

void check_pose(const AnimatedTransform& world_from_camera) {
  const auto& keys = world_from_camera.keys();
  for (size_t k = 0; k < keys.size(); ++k) {
    const std::string key = keys.size() > 1 ? " (key " + std::to_string(k) + ")" : "";
    Point3d origin = keys[k].transform(Point3d(0, 0, 0));
    for (double c : {origin.x, origin.y, origin.z})
      if (!within(c, kMaxWorldCoordinateM))
        throw Error("camera.position" + key, world_coordinate_message(c));
    // A scaled camera scales its ray directions; Embree refuses (aborts on) huge ones.
    for (Vector3d axis : {Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 1)}) {
      double scale = length(keys[k].transform(axis));
      if (!(scale <= kMaxRaySlope && scale >= 1 / kMaxRaySlope))
        throw Error("camera.world_from_camera" + key,
                    "scales the camera by " + number_text(scale) + "; it must be within [" +
                        number_text(1 / kMaxRaySlope) + ", " + number_text(kMaxRaySlope) + "]");
    }
  }
}

void check_perspective(const Camera& camera, const Perspective& p) {
  for (double shift : {p.lens_shift.x, p.lens_shift.y})
    if (!within(shift, 100))
      throw Error("camera.lens_shift",
                  "must be within ±100 (fractions of the sensor); got " + number_text(shift));
  ScreenWindow w = camera.screen_window();
  // Blame whichever is further from a full-frame 50 mm lens: the sensor or the focal length.
  const double sensor_mm = std::max(p.sensor_width_mm, p.sensor_height_mm);
  const char* field =
      sensor_mm / 36 > 50 / p.focal_length_mm ? "camera.sensor_mm" : "camera.focal_length_mm";
  for (double slope : {w.x_min, w.x_max, w.y_min, w.y_max})
    if (!within(slope, kMaxRaySlope))
      throw Error(field,
                  number_text(p.focal_length_mm) + " mm over a " + number_text(p.sensor_width_mm) +
                      "x" + number_text(p.sensor_height_mm) + " mm sensor gives rays " +
                      number_text(std::abs(slope)) + " times wider than deep; at most " +
                      number_text(kMaxRaySlope) + " (a field of view of 179.9999°) can be traced");
  if (camera.lens.depth_of_field) {
    // Rays start anywhere on the aperture: its radius is a world-space offset.
    double diameter_m = aperture_diameter_mm(camera.lens, p.focal_length_mm) / 1000;
    if (!within(diameter_m, kMaxWorldCoordinateM))
      throw Error(
          camera.lens.aperture_diameter_mm ? "camera.aperture_diameter_mm" : "camera.f_number",
          "gives an aperture " + number_text(diameter_m) + " m across; it must be within " +
              number_text(kMaxWorldCoordinateM) +
              " m (beyond that single-precision ray tracing cannot resolve the scene)");
  }
}

void check_orthographic(const Camera& camera, const Orthographic& o) {
  // The view's half width and height are ray-origin offsets from the camera position.
  ScreenWindow w = camera.screen_window();
  for (double c : {w.x_min, w.x_max, w.y_min, w.y_max})
    if (!within(c, kMaxWorldCoordinateM))
      throw Error(o.view_width_m ? "camera.view_width_m" : "camera.view_height_m",
                  "puts ray origins " + number_text(std::abs(c)) + " m from the camera; at most " +
                      number_text(kMaxWorldCoordinateM) +
                      " m (beyond that single-precision ray tracing cannot resolve the scene)");
}

}  // namespace

void validate_world_extent(const Camera& camera) {
  check_pose(camera.world_from_camera);
  if (auto* p = std::get_if<Perspective>(&camera.projection)) check_perspective(camera, *p);
  if (auto* o = std::get_if<Orthographic>(&camera.projection)) check_orthographic(camera, *o);
}

}  // namespace obscura
