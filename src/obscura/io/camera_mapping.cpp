#include "obscura/io/camera_mapping.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr double kDegreesPerRadian = 180 / std::numbers::pi;

// Orthonormal camera→world from a camera at `eye` looking at `target`.
Transform look_at_camera(const JsonReader& json, Vector3d eye, Vector3d target, Vector3d up) {
  Vector3d view = target - eye;
  if (length(view) == 0) json.fail("target", "the camera's target equals its position");
  if (length(cross(normalize(view), up)) < 1e-9)
    json.fail("up", "the up vector is parallel to the viewing direction");
  return inverse(
      Transform::look_at(Point3d(eye.x, eye.y, eye.z), Point3d(target.x, target.y, target.z), up));
}

}  // namespace

SceneCamera perspective_camera(std::string name, const Transform& world_from_camera,
                               double yfov_radians, double aspect_ratio, double z_near,
                               double z_far) {
  SceneCamera c;
  c.name = std::move(name);
  c.projection = CameraProjection::kPerspective;
  c.camera.world_from_camera = world_from_camera;
  c.camera.vertical_fov_degrees = yfov_radians * kDegreesPerRadian;
  c.aspect_ratio = aspect_ratio;
  c.z_near = z_near;
  c.z_far = z_far;
  return c;
}

SceneCamera orthographic_camera(std::string name, const Transform& world_from_camera, double x_mag,
                                double y_mag, double z_near, double z_far) {
  SceneCamera c;
  c.name = std::move(name);
  c.projection = CameraProjection::kOrthographic;
  c.camera.world_from_camera = world_from_camera;  // Camera renders it as a pinhole for now
  c.x_mag = x_mag;
  c.y_mag = y_mag;
  c.aspect_ratio = y_mag > 0 ? x_mag / y_mag : 0;
  c.z_near = z_near;
  c.z_far = z_far;
  return c;
}

SceneCamera camera_from_json(JsonReader& json) {
  SceneCamera c;
  c.name = json.string("name", "camera");
  std::string type = json.string("type", "perspective");
  Vector3d eye = json.vector3("position", {0, 0, 5});
  Vector3d target = json.vector3("target", {0, 0, 0});
  Vector3d up = json.vector3("up", {0, 1, 0});
  c.camera.world_from_camera = look_at_camera(json, eye, target, up);
  c.z_near = json.number_in("near", 0.01, 1e-9, 1e30);
  c.z_far = json.number_in("far", 1e30, c.z_near, 1e30);
  c.aspect_ratio = json.number_in("aspect_ratio", 0, 0, 1e6);
  if (type == "perspective") {
    c.projection = CameraProjection::kPerspective;
    c.sensor_width_mm = json.number_in("sensor_width_mm", 36, 1e-3, 1e4);
    c.sensor_height_mm = json.number_in("sensor_height_mm", 24, 1e-3, 1e4);
    if (json.has("focal_length_mm") && json.has("fov_degrees"))
      json.fail("fov_degrees", "give either fov_degrees or focal_length_mm, not both");
    if (json.has("focal_length_mm")) {
      // Vertical FOV = 2·atan(sensor height / (2·f)).
      c.focal_length_mm = json.number_in("focal_length_mm", 50, 1e-3, 1e5);
      c.camera.vertical_fov_degrees =
          2 * std::atan(c.sensor_height_mm / (2 * c.focal_length_mm)) * kDegreesPerRadian;
    } else {
      c.camera.vertical_fov_degrees = json.number_in("fov_degrees", 40, 1e-3, 179.9);
    }
  } else if (type == "orthographic") {
    c.projection = CameraProjection::kOrthographic;
    c.y_mag = json.number_in("height", 2, 1e-9, 1e30) / 2;
    c.x_mag = c.y_mag * (c.aspect_ratio > 0 ? c.aspect_ratio : 1);
  } else {
    json.fail("type", "unknown camera type '" + type + "'; expected perspective or orthographic");
  }
  c.f_number = json.number_in("f_number", 0, 0, 1e4);
  c.focus_distance = json.number_in("focus_distance", 0, 0, 1e30);
  c.aperture_blades = json.integer("aperture_blades", 0, 0, 64);
  if (c.aperture_blades == 1 || c.aperture_blades == 2)
    json.fail("aperture_blades", "a polygonal aperture needs at least 3 blades (0 = circle)");
  c.shutter_open = json.number("shutter_open", 0);
  c.shutter_close = json.number_in("shutter_close", c.shutter_open, c.shutter_open, 1e30);
  // A moving camera: keyframes of position (and optionally target) over time.
  for (JsonReader& key : json.objects("motion")) {
    double time = key.number("time");
    Vector3d key_eye = key.vector3("position", eye);
    Vector3d key_target = key.vector3("target", target);
    c.motion.push_back({time, look_at_camera(key, key_eye, key_target, up)});
    key.finish();
    if (c.motion.size() > 1 &&
        c.motion.back().time_seconds <= c.motion[c.motion.size() - 2].time_seconds)
      key.fail("time", "motion keys must be in increasing time order");
  }
  json.finish();
  return c;
}

SceneCamera framing_camera(const Bounds3f& bounds) {
  SceneCamera c;
  c.name = "default";
  Bounds3d b(Point3d(bounds.min), Point3d(bounds.max));
  if (bounds.empty()) b = Bounds3d(Point3d(-1, -1, -1), Point3d(1, 1, 1));
  Point3d center = b.center();
  double radius = std::max(1e-3, length(b.diagonal()) / 2);
  double fov = c.camera.vertical_fov_degrees / kDegreesPerRadian;
  // Far enough that the bounding sphere fits in the vertical field of view.
  double distance = radius / std::sin(fov / 2);
  Point3d eye = center + Vector3d(0, 0, distance);
  c.camera.world_from_camera = inverse(Transform::look_at(eye, center, Vector3d(0, 1, 0)));
  c.z_near = std::max(1e-4, (distance - radius) * 0.5);
  c.z_far = distance + 2 * radius;
  return c;
}

void finish_cameras(Scene& scene, const std::string& name, const std::string& where) {
  if (scene.cameras.empty()) scene.cameras.push_back(framing_camera(scene.bounds()));
  const SceneCamera* chosen = &scene.cameras.front();
  if (!name.empty()) {
    auto found = std::find_if(scene.cameras.begin(), scene.cameras.end(),
                              [&](const SceneCamera& c) { return c.name == name; });
    if (found == scene.cameras.end()) {
      std::string known;
      for (const SceneCamera& c : scene.cameras) known += (known.empty() ? "" : ", ") + c.name;
      throw Error(where, "no camera named '" + name + "'; the scene has: " + known);
    }
    chosen = &*found;
  }
  int width = scene.camera.width, height = scene.camera.height;
  scene.camera = chosen->camera;
  scene.camera.width = width;
  scene.camera.height = height;
}

}  // namespace obscura
