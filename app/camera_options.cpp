#include "camera_options.h"

#include <cmath>
#include <vector>

#include "calibrated_camera_options.h"
#include "lens_system_options.h"
#include "number_list_option.h"
#include "obscura/camera/perspective.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"
#include "option_ranges.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

Perspective& perspective_for(Camera& camera, const std::string& option) {
  auto* p = std::get_if<Perspective>(&camera.projection);
  if (!p)
    throw UsageError(option + " applies to a perspective camera; this one is " +
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
  throw UsageError(
      "--projection expects perspective, orthographic, spherical, fisheye or calibrated; got '" +
      name + "'");
}

SensorFit sensor_fit_from_name(const std::string& name) {
  if (name == "auto") return SensorFit::automatic;
  if (name == "horizontal") return SensorFit::horizontal;
  if (name == "vertical") return SensorFit::vertical;
  throw UsageError("--sensor-fit expects auto, horizontal or vertical; got '" + name + "'");
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

void apply_lens_overrides(Camera& camera, const CameraOverrides& o) {
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
    if (!ortho) throw UsageError("--view-height applies to an orthographic camera");
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
      throw UsageError("--focus-breathing expects on or off; got '" + *o.focus_breathing + "'");
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
      throw UsageError(
          "--lens-barrel: the diameter must be positive and the distance not "
          "negative; got '" +
          *o.lens_barrel + "'");
    camera.lens.vignetting.barrel_diameter_mm = v[0];
    camera.lens.vignetting.barrel_distance_mm = v[1];
  }
}

}  // namespace

Shutter shutter_option(const CameraOverrides& o) {
  if (!o.shutter) return Shutter{};
  std::vector<double> times =
      parse_list(*o.shutter, ':', 2, "--shutter", "OPEN:CLOSE in seconds (0:1/60)");
  return {.open_s = times[0], .close_s = times[1]};
}

namespace {

void apply_film_overrides(Camera& camera, const CameraOverrides& o) {
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
      throw UsageError(
          "--rolling-shutter: the line time must be 0 (a global shutter) to 1 s; "
          "got '" +
          text + "'");
    camera.shutter.line_time_s = line_time;
    if (colon != std::string::npos) {
      std::optional<Readout> r = readout_from_name(text.substr(colon + 1));
      if (!r)
        throw UsageError(
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
      throw UsageError("--exposure-mode expects radiance or physical; got '" + *o.exposure_mode +
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
      throw UsageError(std::string("--filter: ") + e.what());
    }
  }
  if (o.near_m) camera.near_m = *o.near_m;
  if (o.far_m) camera.far_m = *o.far_m;
}

}  // namespace

void add_camera_options(CLI::App& command, CameraOverrides& o) {
  const char* group = "Camera (override the scene's camera)";
  command.add_option("--camera", o.camera_name, "Which of the scene's cameras to use, by name")
      ->group(group);
  command
      .add_option("--projection", o.projection,
                  "perspective, orthographic, spherical (equirectangular 360°), fisheye or "
                  "calibrated (K and a lens model: --intrinsics, --distortion, --calibration)")
      ->group(group);
  command
      .add_option("--fov", o.fov_degrees,
                  "Vertical field of view in degrees (glTF's yfov); fisheye: the circle's angle")
      ->check(number_in(0, 360))
      ->group(group);
  command.add_option("--hfov", o.horizontal_fov_degrees, "Horizontal field of view in degrees")
      ->check(number_in(0, 360))
      ->group(group);
  command.add_option("--focal-length", o.focal_length_mm, "Lens focal length in mm")
      ->check(number_in(0, 1e6))
      ->group(group);
  command.add_option("--sensor", o.sensor, "Sensor size WxH in mm, e.g. 36x24")->group(group);
  command.add_option("--sensor-fit", o.sensor_fit, "auto, horizontal or vertical (as Blender)")
      ->group(group);
  command.add_option("--view-height", o.view_height_m, "Orthographic view height in m")
      ->check(number_in(0, 1e12))
      ->group(group);
  command.add_option("--fstop", o.f_number, "Aperture f-number N; turns on depth of field")
      ->check(number_in(0, 1e4))
      ->group(group);
  command
      .add_option("--focus-distance", o.focus_distance_m,
                  "Focus distance in m; turns on depth of field")
      ->check(number_in(0, 1e12))
      ->group(group);
  command
      .add_option("--aperture-blades", o.aperture_blades,
                  "Aperture blades (0 = circle, >= 3 = polygon bokeh); turns on depth of field")
      ->check(integer_in(0, 64))
      ->group(group);
  command
      .add_option("--focus-breathing", o.focus_breathing,
                  "on (default): the sensor moves to the image distance as a real lens focuses; "
                  "off: the field of view stays fixed (Blender Cycles' and pbrt's convention)")
      ->group(group);
  command
      .add_flag("--natural-vignetting", o.natural_vignetting,
                "Thin lens: cos^4 falloff of the light towards the image corners")
      ->group(group);
  command
      .add_option("--lens-barrel", o.lens_barrel,
                  "Thin lens: mechanical vignetting by a barrel opening DIAMETER:DISTANCE (mm, "
                  "in front of the aperture; diameter >= the aperture's): cat-eye bokeh, darker "
                  "corners")
      ->group(group);
  command
      .add_option("--aperture-rotation", o.aperture_rotation_degrees,
                  "Rotation of the aperture polygon in degrees")
      ->check(number_in(-360, 360))
      ->group(group);
  command.add_option("--shutter", o.shutter, "Shutter OPEN:CLOSE in seconds, e.g. 0:1/60")
      ->group(group);
  command
      .add_option("--rolling-shutter", o.rolling_shutter,
                  "Rolling shutter LINE_TIME[:READOUT]: seconds between sensor lines (fractions "
                  "allowed, 1/30000) and top-to-bottom (default), bottom-to-top, left-to-right or "
                  "right-to-left; 0: a global shutter")
      ->group(group);
  command.add_option("--iso", o.iso, "Film speed; selects the physical exposure")
      ->check(number_in(0, 1e7))
      ->group(group);
  command.add_option("--exposure", o.exposure_ev, "Exposure compensation in EV (stops)")
      ->check(number_in(-kMaxExposureEv, kMaxExposureEv))
      ->group(group);
  command
      .add_option("--exposure-mode", o.exposure_mode,
                  "radiance (unscaled, the default) or physical (time x ISO / N^2)")
      ->group(group);
  command.add_option("--crop", o.crop, "Render only x0,y0,x1,y1 (fractions, top-left origin)")
      ->group(group);
  command.add_option("--filter", o.filter, "Pixel filter: box, tent, gaussian or mitchell")
      ->group(group);
  command.add_option("--filter-radius", o.filter_radius_px, "Pixel filter radius in pixels")
      ->check(number_in(0.01, kMaxFilterRadiusPx))
      ->group(group);
  command.add_option("--near", o.near_m, "Near clipping plane in m")
      ->check(number_in(0, 1e12))
      ->group(group);
  command.add_option("--far", o.far_m, "Far clipping plane in m")
      ->check(number_in(0, 1e15))
      ->group(group);
  command
      .add_option("--lens", o.lens,
                  "A real lens traced surface by surface: double-gauss-50mm, telephoto-250mm or "
                  "fisheye-10mm (--fstop stops it down, --focus-distance focuses it)")
      ->group(group);
  command.add_option("--lens-file", o.lens_file, "A lens prescription file (see docs/camera.md)")
      ->group(group);
  command
      .add_option("--lens-coating", o.lens_coating,
                  "A lens system's anti-reflection coating, what its ghost flares reflect: none, "
                  "quarter-wave (MgF2, n 1.38, at 550 nm; the default) or quarter-wave:INDEX[:NM]")
      ->group(group);
  add_calibrated_camera_options(command, o);
}

Camera resolve_camera(const Scene& scene, const CameraOverrides& overrides,
                      std::optional<int> width_px, std::optional<int> height_px) {
  Camera camera = find_camera(scene, overrides.camera_name);
  camera.validate();  // the scene's own mistakes are failures (exit 1), not usage errors
  // A calibration file's mistakes are failures too; its image size is the film's unless
  // --width/--height say otherwise (K then scales).
  apply_calibration_file(camera, overrides);
  if (width_px) camera.film.width_px = *width_px;
  if (height_px) camera.film.height_px = *height_px;
  try {
    apply_lens_overrides(camera, overrides);
    apply_calibrated_overrides(camera, overrides);
    apply_film_overrides(camera, overrides);
    camera.validate();
  } catch (const Error& e) {  // a value given on the command line is out of range
    throw UsageError(std::string("camera option: ") + e.what());
  }
  return camera;
}

}  // namespace obscura::app
