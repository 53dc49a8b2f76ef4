// Cameras: one constructor per camera model, the pose, and the resolved quantities (fields of
// view, focal length, exposure). Projection through the camera and exports: camera_math.cpp.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <numbers>

#include "arrays.h"
#include "bindings.h"
#include "obscura/camera/intrinsics.h"
#include "obscura/io/calibration_file.h"
#include "obscura/io/camera_calibration.h"
#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/error.h"

namespace obscura::python {

namespace {

using Vec3 = std::array<double, 3>;

// What every constructor takes besides its projection: the film, the pose and the exposure.
struct Placement {
  int width, height;
  std::optional<Vec3> position, look_at;
  Vec3 up;
  std::optional<double> near_m, far_m;
  double exposure_ev;
};

#define OBSCURA_PLACEMENT_ARGS                                                                  \
  py::arg("width") = 512, py::arg("height") = 512, py::arg("position") = py::none(),            \
  py::arg("look_at") = py::none(), py::arg("up") = Vec3{0, 1, 0}, py::arg("near") = py::none(), \
  py::arg("far") = py::none(), py::arg("exposure_ev") = 0.0

constexpr const char* kPlacementDoc =
    " Every constructor takes width, height (pixels), position and look_at (world points; the "
    "camera looks from position towards look_at with `up` as close to up as possible; without "
    "them it sits at the origin looking down -Z), near and far (clipping, metres) and "
    "exposure_ev (exposure compensation, EV). Invalid values raise obscura.Error naming them.";

Camera placed(Camera camera, const Placement& p) {
  camera.film.width_px = p.width;
  camera.film.height_px = p.height;
  if (p.position || p.look_at) {
    Point3d eye{0, 0, 0}, target{0, 0, -1};
    if (p.position) eye = {(*p.position)[0], (*p.position)[1], (*p.position)[2]};
    if (p.look_at)
      target = {(*p.look_at)[0], (*p.look_at)[1], (*p.look_at)[2]};
    else
      target = eye + Vector3d{0, 0, -1};
    if (eye == target) throw Error("camera", "position and look_at must differ");
    camera.world_from_camera =
        inverse(Transform::look_at(eye, target, {p.up[0], p.up[1], p.up[2]}));
  }
  if (p.near_m) camera.near_m = *p.near_m;
  if (p.far_m) camera.far_m = *p.far_m;
  camera.exposure.compensation_ev = p.exposure_ev;
  camera.validate();
  return camera;
}

SensorFit sensor_fit_named(const std::string& name) {
  if (name == "auto") return SensorFit::automatic;
  if (name == "horizontal") return SensorFit::horizontal;
  if (name == "vertical") return SensorFit::vertical;
  throw py::value_error("sensor_fit: expected 'auto', 'horizontal' or 'vertical', got '" + name +
                        "'");
}

Intrinsics intrinsics_from(const py::handle& k) {
  py::array a = checked_float_array(k, "K", 3);
  if (a.ndim() != 2 || a.shape(0) != 3)
    throw py::value_error("K: expected a 3x3 matrix [[fx, skew, cx], [0, fy, cy], [0, 0, 1]]");
  std::vector<double> v = as_doubles(a);
  if (v[3] != 0 || v[6] != 0 || v[7] != 0 || v[8] != 1)
    throw py::value_error("K: expected the last row (0, 0, 1) and K[1][0] = 0");
  return {.fx = v[0], .fy = v[4], .cx = v[2], .cy = v[5], .skew = v[1]};
}

Camera perspective(std::optional<double> fov, std::optional<double> horizontal_fov,
                   double focal_length_mm, std::array<double, 2> sensor_mm,
                   const std::string& sensor_fit, std::array<double, 2> lens_shift, double f_number,
                   std::optional<double> focus_distance, bool focus_breathing,
                   const Placement& placement) {
  if (fov && horizontal_fov) throw py::value_error("give fov or horizontal_fov, not both");
  Camera camera;
  Perspective p;
  if (fov)
    p = Perspective::from_vertical_fov_degrees(*fov, sensor_mm[1]);
  else if (horizontal_fov)
    p = Perspective::from_horizontal_fov_degrees(*horizontal_fov, sensor_mm[0]);
  else {
    p.focal_length_mm = focal_length_mm;
    p.sensor_fit = sensor_fit_named(sensor_fit);
  }
  p.sensor_width_mm = sensor_mm[0];
  p.sensor_height_mm = sensor_mm[1];
  p.lens_shift = {lens_shift[0], lens_shift[1]};
  camera.projection = p;
  camera.lens.f_number = f_number;
  camera.lens.focus_breathing = focus_breathing;
  if (focus_distance) {
    camera.lens.depth_of_field = true;
    camera.lens.focus_distance_m = *focus_distance;
  }
  return placed(camera, placement);
}

}  // namespace

void bind_camera(py::module_& m) {
  py::class_<Camera> camera(m, "Camera",
                            "A camera: projection, pose, clipping, lens, shutter, exposure and "
                            "film. Build one with a constructor per model (Camera.perspective, "
                            "thin_lens, orthographic, spherical, fisheye, calibrated, "
                            "from_intrinsics, from_calibration_file) or take a scene's "
                            "(Scene.camera).");
  camera.def(py::init<>(), "The default camera: 50 mm on a 36 x 24 mm sensor, 512 x 512 pixels.");

  camera.def_static(
      "perspective",
      [](std::optional<double> fov, std::optional<double> horizontal_fov, double focal_length_mm,
         std::array<double, 2> sensor_mm, const std::string& sensor_fit,
         std::array<double, 2> lens_shift, double f_number, std::optional<double> focus_distance,
         bool focus_breathing, int width, int height, std::optional<Vec3> position,
         std::optional<Vec3> look_at, Vec3 up, std::optional<double> near_m,
         std::optional<double> far_m, double exposure_ev) {
        return perspective(fov, horizontal_fov, focal_length_mm, sensor_mm, sensor_fit, lens_shift,
                           f_number, focus_distance, focus_breathing,
                           {width, height, position, look_at, up, near_m, far_m, exposure_ev});
      },
      py::arg("fov") = py::none(), py::arg("horizontal_fov") = py::none(),
      py::arg("focal_length_mm") = 50.0, py::arg("sensor_mm") = std::array<double, 2>{36, 24},
      py::arg("sensor_fit") = "auto", py::arg("lens_shift") = std::array<double, 2>{0, 0},
      py::arg("f_number") = 8.0, py::arg("focus_distance") = py::none(),
      py::arg("focus_breathing") = true, OBSCURA_PLACEMENT_ARGS,
      (std::string("A pinhole (perspective) camera: a vertical `fov` or `horizontal_fov` in "
                   "degrees, or a focal length on a sensor (mm) with Blender's sensor fit "
                   "('auto', 'horizontal', 'vertical'); lens_shift as Blender's shift_x/y. "
                   "focus_distance (m) turns on depth of field (a thin lens at f_number).") +
       kPlacementDoc)
          .c_str());

  camera.def_static(
      "thin_lens",
      [](double focus_distance, double f_number, double focal_length_mm,
         std::array<double, 2> sensor_mm, bool focus_breathing, int width, int height,
         std::optional<Vec3> position, std::optional<Vec3> look_at, Vec3 up,
         std::optional<double> near_m, std::optional<double> far_m, double exposure_ev) {
        return perspective(std::nullopt, std::nullopt, focal_length_mm, sensor_mm, "auto", {0, 0},
                           f_number, focus_distance, focus_breathing,
                           {width, height, position, look_at, up, near_m, far_m, exposure_ev});
      },
      py::arg("focus_distance"), py::arg("f_number") = 2.8, py::arg("focal_length_mm") = 50.0,
      py::arg("sensor_mm") = std::array<double, 2>{36, 24}, py::arg("focus_breathing") = true,
      OBSCURA_PLACEMENT_ARGS,
      (std::string("A perspective camera with depth of field: a thin lens of focal_length_mm "
                   "opened to f_number, focused at focus_distance (m).") +
       kPlacementDoc)
          .c_str());

  camera.def_static(
      "orthographic",
      [](double view_height, std::optional<double> view_width, int width, int height,
         std::optional<Vec3> position, std::optional<Vec3> look_at, Vec3 up,
         std::optional<double> near_m, std::optional<double> far_m, double exposure_ev) {
        Camera c;
        c.projection = Orthographic{.view_height_m = view_height, .view_width_m = view_width};
        return placed(c, {width, height, position, look_at, up, near_m, far_m, exposure_ev});
      },
      py::arg("view_height") = 2.0, py::arg("view_width") = py::none(), OBSCURA_PLACEMENT_ARGS,
      (std::string("An orthographic camera seeing view_height x view_width metres (view_width "
                   "defaults to the image's aspect).") +
       kPlacementDoc)
          .c_str());

  camera.def_static(
      "spherical",
      [](int width, int height, std::optional<Vec3> position, std::optional<Vec3> look_at, Vec3 up,
         std::optional<double> near_m, std::optional<double> far_m, double exposure_ev) {
        Camera c;
        c.projection = Equirectangular{};
        return placed(c, {width, height, position, look_at, up, near_m, far_m, exposure_ev});
      },
      OBSCURA_PLACEMENT_ARGS,
      (std::string("An equirectangular (360 x 180 degree) panorama; the image centre looks at "
                   "look_at.") +
       kPlacementDoc)
          .c_str());

  camera.def_static(
      "fisheye",
      [](double fov, int width, int height, std::optional<Vec3> position,
         std::optional<Vec3> look_at, Vec3 up, std::optional<double> near_m,
         std::optional<double> far_m, double exposure_ev) {
        Camera c;
        c.projection = Fisheye{.fov_degrees = fov};
        return placed(c, {width, height, position, look_at, up, near_m, far_m, exposure_ev});
      },
      py::arg("fov") = 180.0, OBSCURA_PLACEMENT_ARGS,
      (std::string("An equidistant circular fisheye seeing `fov` degrees across its image "
                   "circle.") +
       kPlacementDoc)
          .c_str());

  camera.def_static(
      "calibrated",
      [](const py::handle& k, const std::string& distortion, std::vector<double> coefficients,
         std::optional<std::array<int, 2>> calibration_size, double max_field_angle, int width,
         int height, std::optional<Vec3> position, std::optional<Vec3> look_at, Vec3 up,
         std::optional<double> near_m, std::optional<double> far_m, double exposure_ev) {
        CalibratedProjection c;
        c.k = intrinsics_from(k);
        if (calibration_size)
          std::tie(c.width_px, c.height_px) =
              std::pair((*calibration_size)[0], (*calibration_size)[1]);
        if (distortion == "none") {
          if (!coefficients.empty())
            throw py::value_error("distortion 'none' takes no coefficients");
        } else {
          try {
            c.lens = lens_model_from_coefficients(distortion, coefficients);
          } catch (const Error& e) {
            throw py::value_error(std::string("distortion: ") + e.what());
          }
        }
        c.max_field_angle_degrees = max_field_angle;
        Camera camera;
        camera.projection = c;
        return placed(camera, {width, height, position, look_at, up, near_m, far_m, exposure_ev});
      },
      py::arg("K"), py::arg("distortion") = "none", py::arg("coefficients") = std::vector<double>{},
      py::arg("calibration_size") = py::none(), py::arg("max_field_angle") = 0.0,
      OBSCURA_PLACEMENT_ARGS,
      (std::string("A calibrated camera: K (3x3, OpenCV's pixel convention) for an image of "
                   "calibration_size (width, height; default the film's) and a lens model: "
                   "distortion 'none' (a pinhole), 'opencv' (4, 5, 8, 12 or 14 coefficients), "
                   "'kannala-brandt' (4), "
                   "'ftheta' (1-6), 'equidistant', 'equisolid', 'stereographic', "
                   "'orthographic-fisheye' (none). max_field_angle (degrees from the axis, 0: "
                   "the model's limit).") +
       kPlacementDoc)
          .c_str());

  camera.def_static(
      "from_intrinsics",
      [](const py::handle& k, int width, int height, double sensor_width_mm) {
        return camera_from_intrinsics(intrinsics_from(k), width, height, sensor_width_mm);
      },
      py::arg("K"), py::arg("width"), py::arg("height"), py::arg("sensor_width_mm") = 36.0,
      "The perspective camera (no distortion) reproducing K on a width x height image, at the "
      "origin looking down -Z.");

  camera.def_static(
      "from_calibration_file",
      [](const std::string& path, const std::string& image) {
        Camera c;
        apply_calibration(c, read_calibration_file(path, image));
        c.validate();
        return c;
      },
      py::arg("path"), py::arg("image") = "",
      "A camera from a calibration file: OpenCV YAML/JSON, COLMAP text model (folder, "
      "cameras.txt or images.txt) or NeRF transforms.json; `image` picks an image's pose in "
      "COLMAP and NeRF files.");

  camera.def_readwrite("name", &Camera::name, "The camera's name in its scene file.");
  camera.def_property(
      "width", [](const Camera& c) { return c.film.width_px; },
      [](Camera& c, int w) { c.film.width_px = w; }, "Film width in pixels.");
  camera.def_property(
      "height", [](const Camera& c) { return c.film.height_px; },
      [](Camera& c, int h) { c.film.height_px = h; }, "Film height in pixels.");
  camera.def_readwrite("near", &Camera::near_m, "Near clipping distance (m).");
  camera.def_readwrite("far", &Camera::far_m, "Far clipping distance (m).");
  camera.def_property_readonly(
      "projection", [](const Camera& c) { return std::string(projection_name(c.projection)); },
      "'perspective', 'orthographic', 'spherical', 'fisheye' or 'calibrated'.");
  camera.def_property_readonly(
      "fov_degrees",
      [](const Camera& c) {
        Vector2d f = c.fov_degrees();
        return std::pair(f.x, f.y);
      },
      "The resolved (horizontal, vertical) field of view in degrees (orthographic: 0, 0).");
  camera.def_property_readonly("focal_length_mm", &Camera::focal_length_mm,
                               "Focal length (perspective), else 0.");
  camera.def_property_readonly("f_number", &Camera::f_number, "The lens's f-number.");
  camera.def_property_readonly("lens_radius_m", &Camera::lens_radius_m,
                               "Aperture radius in metres (0 without depth of field).");
  camera.def_property_readonly("exposure_scale", &Camera::exposure_scale,
                               "The factor the film applies to radiance (exposure.h).");
  camera.def_property(
      "exposure_ev", [](const Camera& c) { return c.exposure.compensation_ev; },
      [](Camera& c, double ev) { c.exposure.compensation_ev = ev; },
      "Exposure compensation in EV (scales the film by 2^EV).");
  camera.def_property(
      "exposure_mode",
      [](const Camera& c) { return std::string(exposure_mode_name(c.exposure.mode)); },
      [](Camera& c, const std::string& mode) { c.exposure.mode = parse_exposure_mode(mode); },
      "'radiance' (film = radiance x 2^EV) or 'physical' (shutter time, f-number and ISO).");
  camera.def_property(
      "iso", [](const Camera& c) { return c.exposure.iso; },
      [](Camera& c, double iso) { c.exposure.iso = iso; }, "ISO sensitivity (physical mode).");
  camera.def_property(
      "shutter", [](const Camera& c) { return std::pair(c.shutter.open_s, c.shutter.close_s); },
      [](Camera& c, std::pair<double, double> s) {
        c.shutter.open_s = s.first;
        c.shutter.close_s = s.second;
      },
      "(open, close) in seconds.");
  camera.def("validate", &Camera::validate,
             "Raises obscura.Error naming the first invalid parameter.");
  camera.def("__repr__", [](const Camera& c) {
    Vector2d f = c.fov_degrees();
    return "<obscura.Camera " + std::string(projection_name(c.projection)) + " " +
           std::to_string(c.film.width_px) + "x" + std::to_string(c.film.height_px) + " fov " +
           std::to_string(f.x) + " x " + std::to_string(f.y) + " deg>";
  });
  bind_camera_math(camera);
}

}  // namespace obscura::python
