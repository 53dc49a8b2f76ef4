#include "errors.h"

#include "bindings.h"
#include "obscura/math/error.h"
#include "obscura/math/request_error.h"

namespace obscura::python {

namespace {

py::handle g_render_interrupted;

}  // namespace

py::handle render_interrupted_type() {
  return g_render_interrupted;
}

void bind_errors(py::module_& m) {
  // obscura::Error keeps its message (where, what, what was expected); it derives from
  // RuntimeError so that code catching generic runtime failures still catches it.
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  error.doc() =
      "An error reported by Obscura: the message names where (file and line, JSON path, field "
      "or option) and what was expected.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const RequestError& e) {  // a value the caller gave: Python's ValueError
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Error& e) {
      error(e.what());
    }
  });
  // A subclass of KeyboardInterrupt, so that an unhandled Ctrl-C still ends a script as usual,
  // while code that wants the partial render catches it and reads .image / .aovs.
  PyObject* type = PyErr_NewExceptionWithDoc(
      "obscura.RenderInterrupted",
      "Ctrl-C (SIGINT) during render(): the render stopped early. `.image` holds the image "
      "rendered so far (float32, H x W x 3), `.aovs` the requested AOVs, `.result` the whole "
      "RenderResult.",
      PyExc_KeyboardInterrupt, nullptr);
  if (!type) throw py::error_already_set();
  g_render_interrupted = type;
  m.add_object("RenderInterrupted", py::handle(type));
}

}  // namespace obscura::python
