#include "session.h"

#include <pybind11/stl.h>

#include "bindings.h"
#include "obscura/render/camera_request.h"

namespace obscura::python {

Shutter pose_shutter(std::optional<double> time, const std::optional<std::string>& shutter) {
  CameraRequest request;
  request.shutter = shutter;
  Shutter at = requested_shutter(request);
  if (time) {
    const double half = at.duration_s() / 2;
    at.open_s = *time - half;
    at.close_s = *time + half;
  }
  return at;
}

void bind_session(py::module_& m) {
  py::class_<PythonSession>(
      m, "RenderSession",
      "A scene compiled once for many frames: render(session, camera, ...) takes it wherever it "
      "takes a Scene, and keeps the tracer's compiled scene for the next call — again only when "
      "objects move and the camera's exposure interval changes. The session renders a copy of "
      "the scene taken when it was made: later changes to the Scene do not reach it.")
      .def(py::init([](const Scene& scene) {
             auto s = std::make_unique<PythonSession>();
             // Copied with the GIL held (another Python thread may change `scene` as soon as
             // it is free), then validated without it.
             s->scene = std::make_shared<Scene>(scene);
             {
               py::gil_scoped_release release;
               s->scene->validate();
             }
             s->session = std::make_unique<RenderSession>(*s->scene);
             return s;
           }),
           py::arg("scene"))
      .def_property_readonly(
          "scene", [](const PythonSession& s) { return *s.scene; },
          "A copy of the scene the session renders.")
      .def_property_readonly(
          "compilations",
          [](PythonSession& s) {
            std::lock_guard lock(s.busy);
            return s.session->compilations();
          },
          "How many times a renderer has compiled the scene so far (the tracer's integrators share "
          "one compilation; the rasterizer's is the scene as it is).")
      .def_property_readonly(
          "updates",
          [](PythonSession& s) {
            std::lock_guard lock(s.busy);
            return s.session->updates();
          },
          "How many times a renderer brought its compilation up to date in place instead of "
          "compiling again (after pose(), or a still-shutter frame at another moment).")
      .def(
          "pose",
          [](PythonSession& s, double time, std::optional<std::string> shutter) {
            py::gil_scoped_release release;
            std::lock_guard lock(s.busy);
            const Shutter at = pose_shutter(time, shutter);
            s.session->scene_changed(s.scene->pose(at.time_at(0.5), at.duration_s()));
          },
          py::arg("time"), py::arg("shutter") = py::none(),
          "Poses the session's scene at `time` (seconds), as load_scene(..., time=, shutter=) "
          "would have read it: a glTF file's animated skins and morph targets (across the "
          "shutter, for motion blur). Only those meshes are rebuilt before the next render; "
          "nothing changes for a scene without them. render_frames() does this for every frame.")
      .def("__repr__", [](const PythonSession& s) {
        return "<obscura.RenderSession '" + s.scene->name + "'>";
      });
}

}  // namespace obscura::python
