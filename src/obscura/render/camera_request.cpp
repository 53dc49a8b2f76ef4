#include "obscura/render/camera_request.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "obscura/camera/perspective.h"
#include "obscura/math/error.h"
#include "obscura/math/number_list.h"
#include "obscura/math/number_text.h"
#include "obscura/math/request_error.h"
#include "obscura/render/calibrated_camera_request.h"
#include "obscura/render/camera_placement.h"
#include "obscura/render/lens_system_request.h"

namespace obscura {

namespace {

Perspective& perspective_for(Camera& camera, const std::string& option) {
  auto* p = std::get_if<Perspective>(&camera.projection);
  if (!p)
    throw RequestError(option + " applies to a perspective camera; this one is " +
                       std::string(projection_name(camera.projection)) +
                       " (use --projection perspective)");
  return *p;
}

// Switching projection keeps the framing where it can: an orthographic view as tall as the
// perspective view is at the focus distance.
Projection projection_from_name(const std::string& name, const Camera& camera) {
  if (name == "perspective") {
    if (std::holds_alternative<Perspective>(camera.projection)) return camera.projection;
    return Perspective{};
  }
  if (name == "orthographic") {
    if (std::holds_alternative<Orthographic>(camera.projection)) return camera.projection;
    Orthographic o;
    if (std::holds_alternative<Perspective>(camera.projection)) {
      ScreenWindow w = camera.screen_window();
      o.view_height_m = (w.y_max - w.y_min) * camera.lens.focus_distance_m;
    }
    return o;
  }
  if (name == "spherical") return Equirectangular{};
  if (name == "fisheye") {
    if (std::holds_alternative<Fisheye>(camera.projection)) return camera.projection;
    return Fisheye{};
  }
  throw RequestError(
      "--projection expects perspective, orthographic, spherical, fisheye or calibrated; got '" +
      name + "'");
}

SensorFit sensor_fit_from_name(const std::string& name) {
  if (name == "auto") return SensorFit::automatic;
  if (name == "horizontal") return SensorFit::horizontal;
  if (name == "vertical") return SensorFit::vertical;
  throw RequestError("--sensor-fit expects auto, horizontal or vertical; got '" + name + "'");
}

const Camera& find_camera(const Scene& scene, const std::optional<std::string>& name) {
  if (!name || *name == scene.camera.name) return scene.camera;
  // Scene files name all their cameras (Scene::cameras); the render camera is one of them.
  std::string known;
  for (const Camera& c : scene.cameras) {
    if (c.name == *name) return c;
    known += (known.empty() ? "" : ", ") + c.name;
  }
  if (known.empty()) known = scene.camera.name.empty() ? "(one, unnamed)" : scene.camera.name;
  throw Error("--camera",
              "scene '" + scene.name + "' has no camera '" + *name + "'; its cameras: " + known);
}

void apply_lens_overrides(Camera& camera, const CameraRequest& o) {
  if (apply_lens_system_overrides(camera, o)) return;
  if (o.projection && *o.projection != "calibrated") {  // calibrated: calibrated_camera_options
    camera.projection = projection_from_name(*o.projection, camera);
    if (!std::holds_alternative<Perspective>(camera.projection)) camera.lens.depth_of_field = false;
  }
  if (o.sensor) {
    std::string text = *o.sensor;
    for (char& c : text)
      if (c == 'X') c = 'x';
    std::vector<double> size = parse_list(text, 'x', 2, "--sensor", "WxH in mm (36x24)");
    Perspective& p = perspective_for(camera, "--sensor");
    p.sensor_width_mm = size[0];
    p.sensor_height_mm = size[1];
    // A physical sensor fits as Blender's default does (the width spans the larger image
    // dimension), whatever fit the scene's field of view implied; --sensor-fit overrides it.
    p.sensor_fit = SensorFit::automatic;
  }
  if (o.sensor_fit)
    perspective_for(camera, "--sensor-fit").sensor_fit = sensor_fit_from_name(*o.sensor_fit);
  if (o.focal_length_mm)
    perspective_for(camera, "--focal-length").focal_length_mm = *o.focal_length_mm;
  if (o.fov_degrees) {
    if (auto* f = std::get_if<Fisheye>(&camera.projection)) {
      f->fov_degrees = *o.fov_degrees;
    } else {
      Perspective& p = perspective_for(camera, "--fov");
      Perspective fov = Perspective::from_vertical_fov_degrees(*o.fov_degrees, p.sensor_height_mm);
      p.sensor_fit = SensorFit::vertical;
      p.focal_length_mm = fov.focal_length_mm;
    }
  }
  if (o.horizontal_fov_degrees) {
    Perspective& p = perspective_for(camera, "--hfov");
    Perspective fov =
        Perspective::from_horizontal_fov_degrees(*o.horizontal_fov_degrees, p.sensor_width_mm);
    p.sensor_fit = SensorFit::horizontal;
    p.focal_length_mm = fov.focal_length_mm;
  }
  if (o.view_height_m) {
    auto* ortho = std::get_if<Orthographic>(&camera.projection);
    if (!ortho) throw RequestError("--view-height applies to an orthographic camera");
    ortho->view_height_m = *o.view_height_m;
    ortho->view_width_m.reset();
  }
  // Any aperture setting asks for depth of field.
  if (o.f_number || o.focus_distance_m || o.aperture_blades) {
    perspective_for(camera, o.f_number           ? "--fstop"
                            : o.focus_distance_m ? "--focus-distance"
                                                 : "--aperture-blades");
    camera.lens.depth_of_field = true;
  }
  if (o.f_number) {
    camera.lens.f_number = *o.f_number;
    camera.lens.aperture_diameter_mm.reset();
  }
  if (o.focus_distance_m) camera.lens.focus_distance_m = *o.focus_distance_m;
  if (o.aperture_blades) camera.lens.aperture.blades = *o.aperture_blades;
  if (o.focus_breathing) {
    if (*o.focus_breathing != "on" && *o.focus_breathing != "off")
      throw RequestError("--focus-breathing expects on or off; got '" + *o.focus_breathing + "'");
    camera.lens.focus_breathing = *o.focus_breathing == "on";
  }
  if (o.aperture_rotation_degrees)
    camera.lens.aperture.rotation_degrees = *o.aperture_rotation_degrees;
  if (o.natural_vignetting || o.lens_barrel) {
    perspective_for(camera, o.natural_vignetting ? "--natural-vignetting" : "--lens-barrel");
    if (o.natural_vignetting) camera.lens.vignetting.natural = true;
  }
  if (o.lens_barrel) {
    std::vector<double> v =
        parse_list(*o.lens_barrel, ':', 2, "--lens-barrel", "DIAMETER:DISTANCE in mm (40:30)");
    if (!(v[0] > 0) || !(v[1] >= 0))
      throw RequestError(
          "--lens-barrel: the diameter must be positive and the distance not "
          "negative; got '" +
          *o.lens_barrel + "'");
    camera.lens.vignetting.barrel_diameter_mm = v[0];
    camera.lens.vignetting.barrel_distance_mm = v[1];
  }
}

}  // namespace

Shutter requested_shutter(const CameraRequest& o) {
  if (!o.shutter) return Shutter{};
  std::vector<double> times =
      parse_list(*o.shutter, ':', 2, "--shutter", "OPEN:CLOSE in seconds (0:1/60)");
  return {.open_s = times[0], .close_s = times[1]};
}

namespace {

void apply_film_overrides(Camera& camera, const CameraRequest& o) {
  if (o.shutter) {
    std::vector<double> times =
        parse_list(*o.shutter, ':', 2, "--shutter", "OPEN:CLOSE in seconds (0:1/60)");
    camera.shutter.open_s = times[0];
    camera.shutter.close_s = times[1];
  }
  if (o.rolling_shutter) {
    const std::string& text = *o.rolling_shutter;
    size_t colon = text.find(':');
    double line_time = parse_number(text.substr(0, colon), "--rolling-shutter");
    if (!(line_time >= 0 && line_time <= 1))
      throw RequestError(
          "--rolling-shutter: the line time must be 0 (a global shutter) to 1 s; "
          "got '" +
          text + "'");
    camera.shutter.line_time_s = line_time;
    if (colon != std::string::npos) {
      std::optional<Readout> r = readout_from_name(text.substr(colon + 1));
      if (!r)
        throw RequestError(
            "--rolling-shutter expects LINE_TIME[:READOUT] with READOUT "
            "top-to-bottom, bottom-to-top, left-to-right or right-to-left; got '" +
            text + "'");
      camera.shutter.readout = *r;
    }
  }
  if (o.exposure_mode) {
    try {
      camera.exposure.mode = parse_exposure_mode(*o.exposure_mode);
    } catch (const Error&) {
      throw RequestError("--exposure-mode expects radiance or physical; got '" + *o.exposure_mode +
                         "'");
    }
  }
  if (o.iso) {  // a sensitivity only means something for a physical exposure
    camera.exposure.iso = *o.iso;
    camera.exposure.mode = ExposureMode::physical;
  }
  if (o.exposure_ev) camera.exposure.compensation_ev = *o.exposure_ev;
  if (o.crop) {
    std::vector<double> c = parse_list(*o.crop, ',', 4, "--crop", "x0,y0,x1,y1 in [0, 1]");
    camera.film.crop = {.x_min = c[0], .y_min = c[1], .x_max = c[2], .y_max = c[3]};
  }
  if (o.filter || o.filter_radius_px) {
    std::string name = o.filter ? *o.filter : std::string(filter_name(camera.film.filter));
    try {
      camera.film.filter = make_pixel_filter(name, o.filter_radius_px.value_or(0));
    } catch (const Error& e) {
      throw RequestError(std::string("--filter: ") + e.what());
    }
  }
  if (o.near_m) camera.near_m = *o.near_m;
  if (o.far_m) camera.far_m = *o.far_m;
  if (o.time_s) {
    if (!std::isfinite(*o.time_s))
      throw RequestError("--time expects a finite number of seconds; got " +
                         number_text(*o.time_s));
    const double half = camera.shutter.duration_s() / 2;  // the rolling readout stays
    camera.shutter.open_s = *o.time_s - half;
    camera.shutter.close_s = *o.time_s + half;
  }
}

}  // namespace

namespace {

// A calibration's K scaled to a film of another shape stretches the image: say so.
void note_anisotropic_scaling(const Camera& camera, std::vector<std::string>* notes) {
  const auto* calibrated = std::get_if<CalibratedProjection>(&camera.projection);
  if (!notes || !calibrated || calibrated->width_px <= 0 || calibrated->height_px <= 0) return;
  const double sx = double(camera.film.width_px) / calibrated->width_px;
  const double sy = double(camera.film.height_px) / calibrated->height_px;
  if (std::abs(sx - sy) <= 1e-9 * std::max(sx, sy)) return;
  char note[320];
  std::snprintf(
      note, sizeof note,
      "the film (%d x %d px) is not the calibration's shape (%d x %d px): K scales by "
      "%.6g horizontally and %.6g vertically, which stretches the image; give "
      "--width/--height in the calibration's aspect ratio, or leave them out for its size",
      camera.film.width_px, camera.film.height_px, calibrated->width_px, calibrated->height_px, sx,
      sy);
  notes->push_back(note);
}

// --position, --look-at, --up: a fixed pose, placed from the pose at the shutter's opening.
void apply_placement(Camera& camera, const CameraRequest& o, std::vector<std::string>* notes) {
  CameraPlacement placement;
  if (o.position) {
    Vector3d p = parse_placement_vector(*o.position, "--position");
    placement.position = Point3d(p.x, p.y, p.z);
  }
  if (o.look_at) {
    Vector3d p = parse_placement_vector(*o.look_at, "--look-at");
    placement.look_at = Point3d(p.x, p.y, p.z);
  }
  if (o.up) placement.up = parse_placement_vector(*o.up, "--up");
  if (placement.empty()) return;
  if (notes && camera.world_from_camera.is_animated())
    notes->push_back(
        "the camera's keyframed motion is replaced by the fixed pose --position, "
        "--look-at and --up give");
  camera.world_from_camera =
      AnimatedTransform(placed_pose(camera.world_from_camera.at(camera.shutter.open_s), placement));
}

}  // namespace

Camera resolve_camera(const Scene& scene, const CameraRequest& request, std::optional<int> width_px,
                      std::optional<int> height_px, std::vector<std::string>* notes) {
  Camera camera = find_camera(scene, request.camera_name);
  camera.validate();  // the scene's own mistakes are failures (exit 1), not usage errors
  // The film's size, side by side, from the first that gives it: --width/--height, a calibration
  // file's image size, the scene file's render.width/height, 512.
  // A calibration file's mistakes are failures too (and calibration_image without one a
  // request error).
  apply_calibration_file(camera, request);
  if (!request.calibration) {
    camera.film.width_px = scene.render.width.value_or(kDefaultFilmSidePx);
    camera.film.height_px = scene.render.height.value_or(kDefaultFilmSidePx);
  }
  if (width_px) camera.film.width_px = *width_px;
  if (height_px) camera.film.height_px = *height_px;
  try {
    apply_lens_overrides(camera, request);
    apply_calibrated_overrides(camera, request);
    apply_film_overrides(camera, request);
    apply_placement(camera, request, notes);
    camera.validate();
  } catch (const RequestError&) {
    throw;
  } catch (const Error& e) {  // a value given in the request is out of range
    throw RequestError(std::string("camera option: ") + e.what());
  }
  note_anisotropic_scaling(camera, notes);
  return camera;
}

}  // namespace obscura
