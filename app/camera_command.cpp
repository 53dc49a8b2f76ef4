#include "camera_command.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "camera_export.h"
#include "camera_options.h"
#include "obscura/camera/intrinsics.h"
#include "obscura/camera/lens_system_fit.h"
#include "obscura/io/gltf_camera.h"
#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/number_text.h"
#include "option_ranges.h"
#include "render_command.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

struct CameraCommandOptions {
  std::string scene;
  std::optional<int> width, height;
  CameraOverrides overrides;
  std::optional<std::string> export_format, output;
};

std::string num(double v) {
  return number_text(v);
}

// Rounded for reading; the numbers are exact to 6 significant digits.
std::string short_num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

std::string point_text(Point3d p) {
  return "(" + short_num(p.x) + ", " + short_num(p.y) + ", " + short_num(p.z) + ")";
}

const char* fit_name(SensorFit fit) {
  return fit == SensorFit::horizontal ? "horizontal"
         : fit == SensorFit::vertical ? "vertical"
                                      : "auto";
}

void row(const char* label, const std::string& value) {
  std::printf("  %-15s %s\n", label, value.c_str());
}

void print_geometry(const Camera& c) {
  Transform pose = c.world_from_camera.at(c.shutter.open_s);
  Vector3d forward = normalize(pose(Vector3d(0, 0, -1))), up = normalize(pose(Vector3d(0, 1, 0)));
  row("position", point_text(pose(Point3d(0, 0, 0))) + " m, looking " +
                      point_text(Point3d(0, 0, 0) + forward) + ", up " +
                      point_text(Point3d(0, 0, 0) + up) +
                      (c.world_from_camera.is_animated() ? " (animated; at shutter open)" : ""));
  row("projection", std::string(projection_name(c.projection)));
  Vector2d fov = c.fov_degrees();
  if (!std::holds_alternative<Orthographic>(c.projection))
    row("field of view", short_num(fov.x) + "° horizontal, " + short_num(fov.y) + "° vertical");
  if (auto* p = std::get_if<Perspective>(&c.projection)) {
    Vector2d film = c.film_size_mm();
    row("focal length", short_num(p->focal_length_mm) + " mm on a " +
                            short_num(p->sensor_width_mm) + " x " + short_num(p->sensor_height_mm) +
                            " mm sensor (fit " + fit_name(p->sensor_fit) + "; image covers " +
                            short_num(film.x) + " x " + short_num(film.y) + " mm)");
    if (c.lens.depth_of_field)
      row("image distance", short_num(c.image_distance_mm()) + " mm (focused at " +
                                short_num(c.lens.focus_distance_m) + " m)");
    if (p->lens_shift.x != 0 || p->lens_shift.y != 0)
      row("lens shift", short_num(p->lens_shift.x) + ", " + short_num(p->lens_shift.y));
    Intrinsics k = intrinsics(c);
    row("K (OpenCV)", "[" + short_num(k.fx) + " 0 " + short_num(k.cx) + "; 0 " + short_num(k.fy) +
                          " " + short_num(k.cy) + "; 0 0 1] px (pixel centres at integers)");
  }
  if (auto* p = std::get_if<CalibratedProjection>(&c.projection)) {
    Intrinsics k = intrinsics(c);
    row("K (OpenCV)", "[" + short_num(k.fx) + " " + short_num(k.skew) + " " + short_num(k.cx) +
                          "; 0 " + short_num(k.fy) + " " + short_num(k.cy) +
                          "; 0 0 1] px at the film's size (pixel centres at integers)");
    std::string lens = lens_model_name(p->lens);
    std::vector<double> coefficients = lens_model_coefficients(p->lens);
    for (size_t i = 0; i < coefficients.size(); ++i) lens += (i ? "," : ":") + num(coefficients[i]);
    if (p->max_field_angle_degrees > 0)
      lens += ", field limited to " + short_num(p->max_field_angle_degrees) + "° off axis";
    row("distortion", lens);
  }
  if (auto* l = std::get_if<LensSystemProjection>(&c.projection)) {
    auto focused = focused_lens_system(l->lens, c.lens_system_settings());
    const LensSystem& lens = *l->lens;
    row("lens", "'" + lens.name() + "': EFL " + short_num(lens.effective_focal_length_mm()) +
                    " mm, back focal distance " + short_num(lens.back_focal_distance_mm()) +
                    " mm, f/" + short_num(lens.f_number()) + " wide open, " +
                    std::to_string(lens.prescription().surfaces.size()) + " surfaces");
    row("focus", short_num(c.lens.focus_distance_m) + " m from the sensor; sensor " +
                     short_num(focused->film_distance_mm()) + " mm behind the rear vertex, " +
                     short_num(focused->settings().sensor_width_mm) + " x " +
                     short_num(focused->settings().sensor_height_mm) + " mm; iris f/" +
                     short_num(focused->f_number()));
  }
  if (std::holds_alternative<Orthographic>(c.projection)) {
    ScreenWindow w = c.screen_window();
    row("view", short_num(w.x_max - w.x_min) + " x " + short_num(w.y_max - w.y_min) + " m");
  }
  row("clipping", "near " + num(c.near_m) + " m, far " + num(c.far_m) + " m");
}

// A lens system's fitted camera (camera/lens_system_fit.h): what the rasterizer draws it with
// and what --export writes.
void print_fitted_camera(const Camera& c) {
  FittedLensCamera fitted = fitted_lens_camera(c);
  const LensSystemFit& fit = fitted.fit;
  const LensMeasurement& m = fit.measured;
  const CalibratedProjection& p = fit.projection;
  std::string model = lens_model_name(p.lens);
  std::vector<double> coefficients = lens_model_coefficients(p.lens);
  for (size_t i = 0; i < coefficients.size(); ++i)
    model += (i ? "," : ":") + short_num(coefficients[i]);
  if (p.max_field_angle_degrees > 0)
    model += ", field limited to " + short_num(p.max_field_angle_degrees) + "° (image circle " +
             short_num(2 * m.edge_height_mm) + " mm)";
  row("fitted camera", model);
  row("fitted K", "[" + short_num(p.k.fx) + " 0 " + short_num(p.k.cx) + "; 0 " + short_num(p.k.fy) +
                      " " + short_num(p.k.cy) + "; 0 0 1] px (focal length " +
                      short_num(p.k.fx * fitted.sensor_mm.x / c.film.width_px) + " mm; paraxial " +
                      short_num(m.paraxial_focal_length_mm) + " mm)");
  row("centre", short_num(m.centre_of_projection_mm) +
                    " mm in front of the sensor (paraxial entrance pupil " +
                    short_num(m.entrance_pupil_distance_mm) +
                    " mm; chief rays cross the axis within " + short_num(fit.pupil_shift_mm) +
                    " mm of the centre)");
  row("fitted field", short_num(fit.fov_degrees.x) + "° x " + short_num(fit.fov_degrees.y) +
                          "°, diagonal " + short_num(fit.fov_degrees.z) +
                          "° (traced: " + short_num(m.fov_degrees.x) + "° x " +
                          short_num(m.fov_degrees.y) + "°, " + short_num(m.fov_degrees.z) + "°)");
  row("fit residuals",
      "distortion max " + short_num(fit.max_error_px) + " px, RMS " + short_num(fit.rms_error_px) +
          " px at " + std::to_string(c.film.width_px) + " x " + std::to_string(c.film.height_px) +
          "; parallax " + short_num(fit.parallax_px_m) +
          " px·m x |1/D - 1/focus| off the focus plane; illumination table within " +
          short_num(fit.max_illumination_error));
  const double centre = m.field.front().relative_illumination;
  const double corner =
      fit.relative_illumination(std::hypot(fitted.sensor_mm.x, fitted.sensor_mm.y) / 2);
  row("illumination", "relative to the thin lens at f/" + short_num(c.f_number()) + ": centre " +
                          short_num(centre) + ", corner " + short_num(corner) + " (" +
                          short_num(centre > 0 ? corner / centre : 0) + " of the centre)");
}

void print_lens_and_exposure(const Camera& c) {
  if (c.lens.depth_of_field) {
    double diameter = aperture_diameter_mm(c.lens, c.focal_length_mm());
    std::string shape = c.lens.aperture.blades == 0
                            ? "circular"
                            : std::to_string(c.lens.aperture.blades) + " blades, rotated " +
                                  short_num(c.lens.aperture.rotation_degrees) + "°";
    row("lens", "thin lens f/" + short_num(c.f_number()) + ", aperture " + short_num(diameter) +
                    " mm (" + shape + "), lens radius " + short_num(c.lens_radius_m()) +
                    " m, focus " + short_num(c.lens.focus_distance_m) + " m");
  } else if (!std::holds_alternative<LensSystemProjection>(c.projection)) {
    row("lens", "pinhole (depth of field off; f/" + short_num(c.f_number()) + " for exposure)");
  } else if (c.lens.aperture.blades > 0) {
    row("iris", std::to_string(c.lens.aperture.blades) + " blades, rotated " +
                    short_num(c.lens.aperture.rotation_degrees) + "°");
  }
  row("shutter", num(c.shutter.open_s) + " s to " + short_num(c.shutter.close_s) + " s (" +
                     short_num(c.shutter.duration_s()) + " s)");
  if (c.shutter.line_time_s > 0)
    row("rolling", "line time " + short_num(c.shutter.line_time_s) + " s, " +
                       readout_name(c.shutter.readout) + "; the last line closes at " +
                       short_num(c.exposure_interval().close_s) + " s");
  if (c.exposure.mode == ExposureMode::physical)
    row("exposure",
        "physical: ISO " + short_num(c.exposure.iso) + ", EV100 " +
            short_num(ev100(stop_f_number(c.f_number()), c.shutter.duration_s(), c.exposure.iso)) +
            ", compensation " + short_num(c.exposure.compensation_ev) + " EV: radiance x " +
            short_num(c.exposure_scale()));
  else
    row("exposure", "radiance x " + short_num(c.exposure_scale()) + " (compensation " +
                        short_num(c.exposure.compensation_ev) + " EV)");
  Bounds2i crop = c.film.crop_pixels();
  std::string film = std::to_string(c.film.width_px) + " x " + std::to_string(c.film.height_px) +
                     " px, pixel aspect " + short_num(c.film.pixel_aspect) + ", filter " +
                     std::string(filter_name(c.film.filter)) + " radius " +
                     short_num(filter_radius_px(c.film.filter)) + " px";
  row("film", film);
  if (crop.width() != c.film.width_px || crop.height() != c.film.height_px)
    row("crop", "pixels [" + std::to_string(crop.min.x) + ", " + std::to_string(crop.max.x) +
                    ") x [" + std::to_string(crop.min.y) + ", " + std::to_string(crop.max.y) +
                    "): a " + std::to_string(crop.width()) + " x " + std::to_string(crop.height()) +
                    " image");
}

void print_equivalents(const Camera& c) {
  if (c.has_projection_matrix()) {
    GltfCamera g = to_gltf(c);
    if (g.perspective)
      row("glTF", "perspective: yfov " + short_num(g.perspective->yfov_radians) + " rad (" +
                      short_num(g.perspective->yfov_radians * 180 / 3.14159265358979323846) +
                      "°), aspectRatio " + short_num(*g.perspective->aspect_ratio) + ", znear " +
                      num(g.perspective->znear_m) + ", zfar " +
                      (g.perspective->zfar_m ? num(*g.perspective->zfar_m) : "(infinite)"));
    else
      row("glTF", "orthographic: xmag " + short_num(g.orthographic->xmag_m) + ", ymag " +
                      short_num(g.orthographic->ymag_m) + ", znear " +
                      num(g.orthographic->znear_m) + ", zfar " + num(g.orthographic->zfar_m));
  } else {
    row("glTF", "(glTF has no " + std::string(projection_name(c.projection)) + " camera)");
  }
  BlenderCamera b = to_blender(c);
  if (std::string(b.type) == "NONE") {
    row("Blender", "(Blender has no " + std::string(projection_name(c.projection)) + " camera)");
    return;
  }
  std::string blender = std::string("type ") + b.type;
  if (std::string(b.type) == "PERSP")
    blender += ", lens " + short_num(b.lens_mm) + " mm, sensor " + short_num(b.sensor_width_mm) +
               " x " + short_num(b.sensor_height_mm) + " mm, fit " + b.sensor_fit + ", shift " +
               short_num(b.shift_x) + " " + short_num(b.shift_y);
  else if (std::string(b.type) == "ORTHO")
    blender += ", ortho_scale " + short_num(b.ortho_scale);
  else
    blender +=
        std::string(", ") + b.panorama_type +
        (b.fisheye_fov_degrees > 0 ? ", fisheye_fov " + short_num(b.fisheye_fov_degrees) + "°"
                                   : "");
  blender +=
      ", f-stop " + short_num(b.fstop) +
      (b.use_dof ? " (DOF on, focus " + short_num(b.focus_distance_m) + " m)" : " (DOF off)");
  blender += ", clip " + num(b.clip_start_m) + " to " + num(b.clip_end_m) + " m";
  row("Blender", blender);
}

void run_camera(const CameraCommandOptions& options) {
  if (options.width && *options.width <= 0)
    throw UsageError("--width must be a positive number of pixels; got " +
                     std::to_string(*options.width));
  if (options.height && *options.height <= 0)
    throw UsageError("--height must be a positive number of pixels; got " +
                     std::to_string(*options.height));
  if (options.width && options.height) check_image_size(*options.width, *options.height, true);
  Scene scene = load_scene(options.scene);
  if (options.output && !options.export_format) throw UsageError("--output needs --export FORMAT");
  std::vector<std::string> notes;
  Camera camera = resolve_camera(scene, options.overrides, options.width, options.height, &notes);
  for (const std::string& note : notes) std::fprintf(stderr, "warning: %s\n", note.c_str());
  if (options.export_format) {
    export_calibration(camera, *options.export_format, options.output);
    return;
  }
  std::printf("camera '%s' of scene '%s'\n", camera.name.c_str(), scene.name.c_str());
  print_geometry(camera);
  if (std::holds_alternative<LensSystemProjection>(camera.projection)) print_fitted_camera(camera);
  print_lens_and_exposure(camera);
  print_equivalents(camera);
}

}  // namespace

void add_camera_command(CLI::App& app) {
  auto options = std::make_shared<CameraCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "camera", "Print a scene's camera, resolved with the overrides that render accepts");
  command->add_option("scene", options->scene, "A built-in scene name; default: the Cornell box");
  command->add_option("--width", options->width, "Image width in pixels (default: the scene's)")
      ->check(integer_in(1, kMaxImageSidePx));
  command->add_option("--height", options->height, "Image height in pixels (default: the scene's)")
      ->check(integer_in(1, kMaxImageSidePx));
  add_camera_options(*command, options->overrides);
  command
      ->add_option("--export", options->export_format,
                   "Print the resolved camera as a calibration file: opencv-yaml, opencv-json, "
                   "nerf (transforms.json) or colmap (needs --output FOLDER)")
      ->group("Export");
  command
      ->add_option("--output", options->output,
                   "Write the export to this file (colmap: this folder) instead of stdout")
      ->group("Export");
  command->callback([options] { run_camera(*options); });
}

}  // namespace obscura::app
