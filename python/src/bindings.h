// The Python module's parts, one per concept; module.cpp calls each to add its names.
#pragma once
#include <pybind11/pybind11.h>

#include "obscura/camera/camera.h"

namespace obscura::python {

namespace py = pybind11;

void bind_errors(py::module_& m);  // obscura.Error, obscura.RenderInterrupted
void bind_image(py::module_& m);   // read_image, write_image, read_exr
void bind_color(py::module_& m);   // convert, develop, wavelength and blackbody colours
void bind_camera(py::module_& m);  // Camera and its constructors
void bind_camera_math(py::class_<Camera>& camera);  // project, unproject, K, exports
void bind_scene(py::module_& m);           // Scene, load_scene, built-in scenes, scenes from arrays
void bind_render(py::module_& m);          // render() and RenderResult
void bind_camera_request(py::module_& m);  // resolve_camera(): the command line's camera options
void bind_ground_truth(py::module_& m);    // ground_truth(): the --ground-truth channels
void bind_session(py::module_& m);         // RenderSession: a scene compiled once for many frames
void bind_dataset(py::module_& m);         // render_dataset(): views, images, calibrations
void bind_motion(py::module_& m);          // motion keys of cameras and instances
void bind_sensor(py::module_& m);  // capture_raw, develop_raw, write_dng, meter: the raw sensor

}  // namespace obscura::python
