// The camera's geometry on arrays: vectorized project / unproject (Camera::project and
// Camera::unproject, the functions both renderers agree with), K, the pose, and the calibration
// exports of `obscura camera --export` (io/calibration_file.h, io/colmap_model.h).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>

#include "arrays.h"
#include "bindings.h"
#include "obscura/camera/intrinsics.h"
#include "obscura/camera/point_projection.h"
#include "obscura/io/atomic_file.h"
#include "obscura/io/calibration_file.h"
#include "obscura/io/camera_calibration.h"
#include "obscura/io/colmap_model.h"
#include "obscura/math/error.h"

namespace obscura::python {

namespace {

void write_text(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.write(text);
  file.commit();
}

}  // namespace

void bind_camera_math(py::class_<Camera>& camera) {
  camera.def(
      "project",
      [](const Camera& camera, const py::handle& points, double time) {
        const Camera c = camera;  // the GIL is freed below: another thread may change `camera`
        // Finite values are checked in the parallel loop below, not in a serial pass here.
        py::array in = checked_points(points, "project(points)", 3, /*finite=*/false);
        const size_t n = size_t(in.shape(0));
        const py::ssize_t count = py::ssize_t(n);
        py::array_t<double> film({count, py::ssize_t(2)}), depth(count);
        double* film_out = film.mutable_data();
        double* depth_out = depth.mutable_data();
        const bool is_f32 = in.dtype().is(py::dtype::of<float>());
        const void* world = in.data();  // `in` holds the array while the GIL is free
        bool finite = true;
        {
          py::gil_scoped_release release;
          finite = is_f32 ? project_points(c, static_cast<const float*>(world), n, time, film_out,
                                           depth_out)
                          : project_points(c, static_cast<const double*>(world), n, time, film_out,
                                           depth_out);
        }
        if (!finite)
          throw py::value_error("project(points): expected finite values, found NaN or Inf");
        return py::make_tuple(film, depth);
      },
      py::arg("points"), py::arg("time") = 0.0,
      "Projects world points (N, 3) onto the film at `time`: returns (film (N, 2) raster "
      "coordinates in pixels, pixel centres at half-integers, y down; depth (N,) in metres: "
      "along -Z for perspective, orthographic and calibrated pinholes, distance for spherical "
      "and fisheye cameras). Points the camera does not see get NaN.");

  camera.def(
      "unproject",
      [](const Camera& camera, const py::handle& film_points, const py::handle& depths,
         double time) {
        const Camera c = camera;  // the GIL is freed below: another thread may change `camera`
        py::array f = checked_points(film_points, "unproject(film)", 2);
        py::array d = checked_float_array(depths, "unproject(depth)", 0);
        if (d.ndim() != 1 || d.shape(0) != f.shape(0))
          throw py::value_error("unproject(depth): expected shape (" + std::to_string(f.shape(0)) +
                                ",), one depth per film point");
        // One element type for both inputs (a float32 one widens exactly to float64).
        const bool is_f32 =
            f.dtype().is(py::dtype::of<float>()) && d.dtype().is(py::dtype::of<float>());
        if (!is_f32) {
          f = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(f);
          d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(d);
        }
        const size_t n = size_t(d.shape(0));
        py::array_t<double> world({py::ssize_t(n), py::ssize_t(3)});
        double* out = world.mutable_data();
        const void *film_in = f.data(), *depth_in = d.data();
        {
          py::gil_scoped_release release;
          if (is_f32)
            unproject_points(c, static_cast<const float*>(film_in),
                             static_cast<const float*>(depth_in), n, time, out);
          else
            unproject_points(c, static_cast<const double*>(film_in),
                             static_cast<const double*>(depth_in), n, time, out);
        }
        return world;
      },
      py::arg("film"), py::arg("depth"), py::arg("time") = 0.0,
      "The world points (N, 3) at raster points `film` (N, 2) and depths (N,) as project() gives "
      "them: unproject(*project(p)) == p. NaN where the camera sees nothing.");

  camera.def_property_readonly(
      "K",
      [](const Camera& c) {
        Intrinsics k = intrinsics(c);
        py::array_t<double> out({3, 3});
        auto a = out.mutable_unchecked<2>();
        const double rows[3][3] = {{k.fx, k.skew, k.cx}, {0, k.fy, k.cy}, {0, 0, 1}};
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) a(i, j) = rows[i][j];
        return out;
      },
      "The intrinsics matrix K (3x3) in OpenCV's conventions (integer pixel centres) at the "
      "film's resolution: perspective and calibrated cameras; others raise obscura.Error.");

  camera.def_property(
      "world_from_camera",
      [](const Camera& c) {
        return matrix_to_array(c.world_from_camera.at(c.shutter.open_s).matrix());
      },
      [](Camera& c, const py::handle& m) {
        c.world_from_camera = Transform(array_to_matrix(m, "world_from_camera"));
      },
      "The pose (4x4, camera -> world; camera space: X right, Y up, looking down -Z) at the "
      "shutter's open time. Assigning one makes the camera still.");

  camera.def(
      "look_at",
      [](Camera& c, std::array<double, 3> position, std::array<double, 3> target,
         std::array<double, 3> up) {
        Point3d eye{position[0], position[1], position[2]}, at{target[0], target[1], target[2]};
        if (eye == at) throw Error("look_at", "position and target must differ");
        c.world_from_camera = inverse(Transform::look_at(eye, at, {up[0], up[1], up[2]}));
      },
      py::arg("position"), py::arg("target"), py::arg("up") = std::array<double, 3>{0, 1, 0},
      "Places the camera at `position` looking at `target`.");

  camera.def(
      "export",
      [](const Camera& c, const std::string& format_name,
         std::optional<std::string> path) -> std::optional<std::string> {
        std::optional<CalibrationFormat> format = calibration_format_from_name(format_name);
        if (!format)
          throw py::value_error(
              "export: expected 'opencv-yaml', 'opencv-json', 'colmap' or "
              "'nerf', got '" +
              format_name + "'");
        CameraCalibration calibration = calibration_of(c);
        if (*format == CalibrationFormat::colmap) {
          if (!path) throw py::value_error("export('colmap') writes a folder: give path=FOLDER");
          ColmapModelText model = colmap_model_text(calibration);
          namespace fs = std::filesystem;
          std::error_code error;
          fs::create_directories(*path, error);
          if (!fs::is_directory(*path)) throw Error(*path, "export('colmap') needs a folder");
          write_text((fs::path(*path) / "cameras.txt").string(), model.cameras);
          write_text((fs::path(*path) / "images.txt").string(), model.images);
          write_text((fs::path(*path) / "points3D.txt").string(), "# Number of points: 0\n");
          return std::nullopt;
        }
        std::string text = calibration_text(*format, calibration);
        if (!path) return text;
        write_text(*path, text);
        return std::nullopt;
      },
      py::arg("format"), py::arg("path") = py::none(),
      "The camera as a calibration file, as `obscura camera --export` writes it: 'opencv-yaml', "
      "'opencv-json' or 'nerf' return the text (or write it to `path`); 'colmap' writes "
      "cameras.txt, images.txt and points3D.txt into the folder `path`. Raises obscura.Error "
      "for a camera the format cannot describe.");
}

}  // namespace obscura::python
