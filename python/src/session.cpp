#include "session.h"

#include "bindings.h"

namespace obscura::python {

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
             s->scene = std::make_shared<const Scene>(scene);
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
      .def("__repr__", [](const PythonSession& s) {
        return "<obscura.RenderSession '" + s.scene->name + "'>";
      });
}

}  // namespace obscura::python
