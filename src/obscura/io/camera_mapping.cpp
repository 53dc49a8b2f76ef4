#include "obscura/io/camera_mapping.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "obscura/camera/builtin_lenses.h"
#include "obscura/camera/frames.h"
#include "obscura/camera/lens_coating.h"
#include "obscura/io/calibrated_camera_json.h"
#include "obscura/io/lens_file.h"
#include "obscura/io/sensor_json.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr double kDegreesPerRadian = 180 / std::numbers::pi;

// Camera→world of a camera at `eye` looking at `target`.
Transform look_at(const JsonReader& json, Vector3d eye, Vector3d target, Vector3d up) {
  Vector3d view = target - eye;
  if (length(view) == 0) json.fail("target", "the camera's target equals its position");
  if (length(up) == 0 || length(cross(normalize(view), normalize(up))) < 1e-9)
    json.fail("up", "the up vector is zero or parallel to the viewing direction");
  return world_from_camera_look_at(Point3d(eye.x, eye.y, eye.z),
                                   Point3d(target.x, target.y, target.z), up);
}

// Runs a camera-layer constructor, putting the file's location in front of its message.
template <typename F>
Camera located(const std::string& where, F&& make) {
  try {
    return make();
  } catch (const Error& e) {
    throw Error(where, e.what());
  }
}

SensorFit parse_sensor_fit(JsonReader& json) {
  std::string fit = json.string("sensor_fit", "auto");
  if (fit == "auto") return SensorFit::automatic;
  if (fit == "horizontal") return SensorFit::horizontal;
  if (fit == "vertical") return SensorFit::vertical;
  json.fail("sensor_fit", "expected auto, horizontal or vertical; got '" + fit + "'");
}

Perspective perspective_from_json(JsonReader& json) {
  int given =
      json.has("fov_degrees") + json.has("horizontal_fov_degrees") + json.has("focal_length_mm");
  if (given > 1)
    json.fail("fov_degrees", "give one of fov_degrees, horizontal_fov_degrees or focal_length_mm");
  double sensor_width = json.number_in("sensor_width_mm", 36, 1e-3, 1e4);
  double sensor_height = json.number_in("sensor_height_mm", 24, 1e-3, 1e4);
  Perspective p;
  if (json.has("fov_degrees")) {
    p = Perspective::from_vertical_fov_degrees(json.number_in("fov_degrees", 40, 1e-3, 179.9),
                                               sensor_height);
    p.sensor_width_mm = sensor_width;
  } else if (json.has("horizontal_fov_degrees")) {
    p = Perspective::from_horizontal_fov_degrees(
        json.number_in("horizontal_fov_degrees", 40, 1e-3, 179.9), sensor_width);
    p.sensor_height_mm = sensor_height;
  } else {
    p.focal_length_mm = json.number_in("focal_length_mm", 50, 1e-3, 1e5);
    p.sensor_width_mm = sensor_width;
    p.sensor_height_mm = sensor_height;
    p.sensor_fit = parse_sensor_fit(json);
  }
  if (json.has("lens_shift")) {
    std::vector<double> shift = json.numbers("lens_shift", 2);
    p.lens_shift = {shift[0], shift[1]};
  }
  return p;
}

// A lens-system camera: a built-in lens by name or a prescription file (relative to the scene
// file), the sensor's width, an f-number that stops the iris down, and its coating.
LensSystemProjection lens_system_from_json(JsonReader& json) {
  if (json.has("lens") == json.has("lens_file"))
    json.fail("lens", "a lens_system camera needs one of lens (a built-in name) or lens_file");
  LensSystemProjection p;
  try {
    if (json.has("lens")) {
      p.lens = builtin_lens(json.string("lens"));
    } else {
      std::filesystem::path file(json.string("lens_file"));
      if (file.is_relative()) file = std::filesystem::path(json.file()).parent_path() / file;
      p.lens = std::make_shared<const LensSystem>(load_checked_lens_prescription(file.string()));
    }
  } catch (const Error& e) {
    json.fail(json.has("lens") ? "lens" : "lens_file", e.what());
  }
  p.sensor_width_mm = json.number_in("sensor_width_mm", 36, 1e-3, 1e4);
  if (json.has("f_number")) p.f_number = json.number_in("f_number", 0, 1e-3, 1e4);
  if (json.has("coating")) {
    try {
      p.coating = parse_lens_coating(json.string("coating"));
    } catch (const Error& e) {
      std::string message = e.what();
      json.fail("coating", message.substr(e.where().size() + 2));  // without parse's own field
    }
  }
  return p;
}

}  // namespace

Camera gltf_perspective_camera(std::string name, const Transform& world_from_camera,
                               const GltfPerspective& perspective, const std::string& where) {
  Camera c = located(where, [&] { return from_gltf_perspective(perspective); });
  c.name = std::move(name);
  c.world_from_camera = world_from_camera;
  return c;
}

Camera gltf_orthographic_camera(std::string name, const Transform& world_from_camera,
                                const GltfOrthographic& orthographic, const std::string& where) {
  Camera c = located(where, [&] { return from_gltf_orthographic(orthographic); });
  c.name = std::move(name);
  c.world_from_camera = world_from_camera;
  return c;
}

Camera camera_from_json(JsonReader& json) {
  Camera c;
  c.name = json.string("name", "camera");
  std::string type = json.string("type", "perspective");
  Vector3d eye = json.vector3("position", {0, 0, 5});
  Vector3d target = json.vector3("target", {0, 0, 0});
  Vector3d up = json.vector3("up", {0, 1, 0});
  Transform pose = look_at(json, eye, target, up);
  c.near_m = json.number_in("near", type == "orthographic" ? 0 : 0.01, 0, 1e30);
  c.far_m = json.has("far") ? json.number_in("far", 0, 0, 1e300)
                            : std::numeric_limits<double>::infinity();
  if (type == "perspective") {
    c.projection = perspective_from_json(json);
  } else if (type == "orthographic") {
    Orthographic o;
    o.view_height_m = json.number_in("height", 2, 1e-9, 1e30);
    if (json.has("width")) o.view_width_m = json.number_in("width", 2, 1e-9, 1e30);
    c.projection = o;
  } else if (type == "spherical") {
    c.projection = Equirectangular{};
  } else if (type == "fisheye") {
    c.projection = Fisheye{.fov_degrees = json.number_in("fisheye_fov_degrees", 180, 1e-3, 360)};
  } else if (type == "calibrated") {
    c.projection = calibrated_projection_from_json(json);
  } else if (type == "lens_system") {
    c.projection = lens_system_from_json(json);
  } else {
    json.fail("type", "unknown camera type '" + type +
                          "'; expected perspective, orthographic, spherical, fisheye, calibrated "
                          "or lens_system");
  }
  // Thin lens: an f-number or aperture diameter turns depth of field on.
  if (json.has("f_number") || json.has("aperture_diameter_mm")) c.lens.depth_of_field = true;
  c.lens.f_number = json.number_in("f_number", c.lens.f_number, 1e-3, 1e4);
  if (json.has("aperture_diameter_mm"))
    c.lens.aperture_diameter_mm = json.number_in("aperture_diameter_mm", 1, 1e-6, 1e4);
  c.lens.focus_distance_m = json.number_in("focus_distance", length(target - eye), 1e-6, 1e30);
  c.lens.focus_breathing = json.boolean("focus_breathing", true);
  c.lens.aperture.blades = json.integer("aperture_blades", 0, 0, 64);
  c.lens.aperture.rotation_degrees = json.number("aperture_rotation_degrees", 0);
  // A lens system always has depth of field; its f-number is its own (lens_system_from_json).
  if (std::holds_alternative<LensSystemProjection>(c.projection)) c.lens.depth_of_field = false;
  if (json.has("vignetting")) {
    JsonReader v = json.object("vignetting");
    c.lens.vignetting.natural = v.boolean("natural", false);
    c.lens.vignetting.barrel_diameter_mm = v.number_in("barrel_diameter_mm", 0, 0, 1e5);
    c.lens.vignetting.barrel_distance_mm = v.number_in("barrel_distance_mm", 0, 0, 1e5);
    v.finish();
  }
  c.shutter.open_s = json.number("shutter_open", c.shutter.open_s);
  c.shutter.close_s = json.number("shutter_close", c.shutter.close_s);
  c.shutter.line_time_s = json.number_in("rolling_shutter_line_time", 0, 0, 1);
  if (json.has("rolling_shutter_readout")) {
    std::string readout = json.string("rolling_shutter_readout");
    std::optional<Readout> r = readout_from_name(readout);
    if (!r)
      json.fail("rolling_shutter_readout",
                "expected top-to-bottom, bottom-to-top, left-to-right or right-to-left; got '" +
                    readout + "'");
    c.shutter.readout = *r;
  }
  if (json.has("exposure_mode")) {
    std::string mode = json.string("exposure_mode");
    try {
      c.exposure.mode = parse_exposure_mode(mode);
    } catch (const Error& e) {
      json.fail("exposure_mode", e.what());
    }
  }
  c.exposure.compensation_ev = json.number("exposure_compensation_ev", 0);
  c.exposure.iso = json.number_in("iso", 100, 1e-3, 1e7);
  c.film.pixel_aspect = json.number_in("pixel_aspect", 1, 1e-3, 1e3);
  // The raw sensor is checked here, where its JSON path is known, and read back by the camera's
  // name when a frame is captured (io/sensor_json.h).
  if (json.has("sensor")) sensor_from_json(json.object("sensor"));
  // A moving camera: keyframes of position (and target) over time.
  std::vector<AnimatedTransform::Key> keys;
  for (JsonReader& key : json.objects("motion")) {
    double time = key.number("time");
    if (!keys.empty() && time <= keys.back().time_s)
      key.fail("time", "motion keys must be in increasing time order");
    keys.push_back(
        {time, look_at(key, key.vector3("position", eye), key.vector3("target", target), up)});
    key.finish();
  }
  c.world_from_camera = keys.empty() ? AnimatedTransform(pose) : AnimatedTransform(keys);
  json.finish();
  std::string where = json.file() + ": " + json.path();
  return located(where, [&] {
    c.validate();
    return c;
  });
}

Camera framing_camera(const Bounds3f& bounds) {
  Camera c;
  c.name = "default";
  Perspective p = Perspective::from_vertical_fov_degrees(40);
  c.projection = p;
  Bounds3d b(Point3d(bounds.min), Point3d(bounds.max));
  if (bounds.empty()) b = Bounds3d(Point3d(-1, -1, -1), Point3d(1, 1, 1));
  Point3d center = b.center();
  double radius = std::max(1e-3, length(b.diagonal()) / 2);
  // Far enough that the bounding sphere fits in the vertical field of view, from a three-quarter
  // view (35° to the right of the front, +Z, and 25° above), as model viewers frame a model: a
  // flat model (a plane, a decal) is never seen exactly edge-on, and a box shows three faces.
  double distance = radius / std::sin(20 / kDegreesPerRadian);
  const double azimuth = 35 / kDegreesPerRadian, elevation = 25 / kDegreesPerRadian;
  Vector3d toward_eye(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                      std::cos(azimuth) * std::cos(elevation));
  Point3d eye = center + toward_eye * distance;
  c.world_from_camera = world_from_camera_look_at(eye, center);
  c.near_m = std::max(1e-4, (distance - radius) * 0.5);
  c.far_m = distance + 2 * radius;
  c.lens.focus_distance_m = distance;
  return c;
}

void finish_cameras(Scene& scene, const std::string& name, const std::string& where) {
  if (scene.cameras.empty()) scene.cameras.push_back(framing_camera(scene.bounds()));
  const Camera* chosen = &scene.cameras.front();
  if (!name.empty()) {
    auto found = std::find_if(scene.cameras.begin(), scene.cameras.end(),
                              [&](const Camera& c) { return c.name == name; });
    if (found == scene.cameras.end()) {
      std::string known;
      for (const Camera& c : scene.cameras) known += (known.empty() ? "" : ", ") + c.name;
      throw Error(where, "no camera named '" + name + "'; the scene has: " + known);
    }
    chosen = &*found;
  }
  scene.camera = *chosen;
}

}  // namespace obscura
