// resolve_camera(): the camera `obscura render` renders with, from the same request in keyword
// form — the command line's camera options with their dashes as underscores (--lens-file →
// lens_file, --fstop → fstop), the same values and forms ("0:1/60", "36x24"). Through it a
// Python user has every camera the command line has: lens systems and prescription files,
// coatings, calibration files, rolling shutters, crops, filters, exposure.
#include <pybind11/stl.h>

#include "bindings.h"
#include "obscura/math/number_text.h"
#include "obscura/render/camera_request.h"

namespace obscura::python {

namespace {

using Text = std::optional<std::string>;
using Number = std::optional<double>;
using Triple = std::optional<std::vector<double>>;

// A placement keyword ((x, y, z)) in the command line's form "x,y,z", exactly.
Text triple_text(const Triple& v) {
  if (!v) return std::nullopt;
  std::string text;
  for (double x : *v) {
    if (!text.empty()) text += ',';  // appended, not "," + …: GCC 12 warns falsely on that
    text += number_text(x);
  }
  return text;
}

Camera resolve_camera_py(const Scene& scene, Text camera, std::optional<int> width,
                         std::optional<int> height, Text projection, Number fov, Number hfov,
                         Number focal_length, Text sensor, Text sensor_fit, Number view_height,
                         Number fstop, Number focus_distance, std::optional<int> aperture_blades,
                         Number aperture_rotation, std::optional<bool> focus_breathing,
                         bool natural_vignetting, Text lens_barrel, Text shutter,
                         Text rolling_shutter, Number iso, Number exposure, Text exposure_mode,
                         Text crop, Text filter, Number filter_radius, Number near, Number far,
                         Text intrinsics, Text calibration_size, Text distortion,
                         Number max_field_angle, Text calibration, Text calibration_image,
                         Text lens, Text lens_file, Text lens_coating, Number time, Triple position,
                         Triple look_at, Triple up) {
  CameraRequest r;
  r.camera_name = camera;
  r.projection = projection;
  r.fov_degrees = fov;
  r.horizontal_fov_degrees = hfov;
  r.focal_length_mm = focal_length;
  r.sensor = sensor;
  r.sensor_fit = sensor_fit;
  r.view_height_m = view_height;
  r.f_number = fstop;
  r.focus_distance_m = focus_distance;
  r.aperture_blades = aperture_blades;
  r.aperture_rotation_degrees = aperture_rotation;
  if (focus_breathing) r.focus_breathing = *focus_breathing ? "on" : "off";
  r.natural_vignetting = natural_vignetting;
  r.lens_barrel = lens_barrel;
  r.shutter = shutter;
  r.rolling_shutter = rolling_shutter;
  r.iso = iso;
  r.exposure_ev = exposure;
  r.exposure_mode = exposure_mode;
  r.crop = crop;
  r.filter = filter;
  r.filter_radius_px = filter_radius;
  r.near_m = near;
  r.far_m = far;
  r.intrinsics = intrinsics;
  r.calibration_size = calibration_size;
  r.distortion = distortion;
  r.max_field_angle_degrees = max_field_angle;
  r.calibration = calibration;
  r.calibration_image = calibration_image;
  r.lens = lens;
  r.lens_file = lens_file;
  r.lens_coating = lens_coating;
  r.time_s = time;
  r.position = triple_text(position);
  r.look_at = triple_text(look_at);
  r.up = triple_text(up);
  std::vector<std::string> notes;
  Camera resolved;
  // Another Python thread may change `scene` while the GIL is free: resolve from a copy of what
  // resolve_camera reads (the cameras and the render settings), taken with the GIL held.
  Scene cameras_of;
  cameras_of.name = scene.name;
  cameras_of.cameras = scene.cameras;
  cameras_of.camera = scene.camera;
  cameras_of.render = scene.render;
  {
    py::gil_scoped_release release;  // a calibration or prescription file is read
    resolved = resolve_camera(cameras_of, r, width, height, &notes);
  }
  for (const std::string& note : notes)
    if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) != 0) throw py::error_already_set();
  return resolved;
}

}  // namespace

void bind_camera_request(py::module_& m) {
  const py::none none;
  m.def("resolve_camera", &resolve_camera_py, py::arg("scene"), py::kw_only(),
        py::arg("camera") = none, py::arg("width") = none, py::arg("height") = none,
        py::arg("projection") = none, py::arg("fov") = none, py::arg("hfov") = none,
        py::arg("focal_length") = none, py::arg("sensor") = none, py::arg("sensor_fit") = none,
        py::arg("view_height") = none, py::arg("fstop") = none, py::arg("focus_distance") = none,
        py::arg("aperture_blades") = none, py::arg("aperture_rotation") = none,
        py::arg("focus_breathing") = none, py::arg("natural_vignetting") = false,
        py::arg("lens_barrel") = none, py::arg("shutter") = none, py::arg("rolling_shutter") = none,
        py::arg("iso") = none, py::arg("exposure") = none, py::arg("exposure_mode") = none,
        py::arg("crop") = none, py::arg("filter") = none, py::arg("filter_radius") = none,
        py::arg("near") = none, py::arg("far") = none, py::arg("intrinsics") = none,
        py::arg("calibration_size") = none, py::arg("distortion") = none,
        py::arg("max_field_angle") = none, py::arg("calibration") = none,
        py::arg("calibration_image") = none, py::arg("lens") = none, py::arg("lens_file") = none,
        py::arg("lens_coating") = none, py::arg("time") = none, py::arg("position") = none,
        py::arg("look_at") = none, py::arg("up") = none,
        "The camera `obscura render SCENE [camera options]` renders with: the scene's camera "
        "(by name: camera=) with the command line's camera options as keywords, their dashes "
        "as underscores and their values in the same units and forms (fstop=2.8, "
        "focus_distance=3, shutter='0:1/60', rolling_shutter='1/30000', sensor='36x24', "
        "lens='double-gauss-50mm', lens_file=PATH, lens_coating='none', calibration=PATH, "
        "calibration_image=NAME, crop='0.25,0.25,0.75,0.75', …; docs/camera.md); time= "
        "centres the shutter on that moment, as --time does; position=, look_at=, up= (x, y, z) "
        "place the camera as --position, --look-at and --up do. The film's "
        "size is width/height when given, else a calibration file's image size, else the scene "
        "file's render.width/height, else 512 x 512. A film whose shape stretches a "
        "calibration's K gives a UserWarning. A malformed or out-of-range value raises "
        "ValueError naming the option; an unknown camera or unreadable file raises "
        "obscura.Error.");
}

}  // namespace obscura::python
