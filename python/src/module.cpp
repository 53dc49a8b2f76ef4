// The `obscura` Python module (python/obscura/_obscura): the library's scenes, cameras, renderers,
// colour pipeline and image files on numpy arrays. docs/python.md shows it in use.
#include <pybind11/pybind11.h>

#include "bindings.h"

PYBIND11_MODULE(_obscura, m) {
  using namespace obscura::python;
  m.doc() =
      "Obscura, a physical-camera rendering engine: load or build scenes, choose cameras, render "
      "with the path tracer or the rasterizer into numpy arrays, and convert colours.";
  m.attr("__version__") = OBSCURA_VERSION;
  bind_errors(m);
  bind_image(m);
  bind_color(m);
  bind_camera(m);
  bind_scene(m);
  bind_motion(m);
  bind_session(m);
  bind_render(m);
  bind_camera_request(m);
  bind_ground_truth(m);
  bind_dataset(m);
  bind_sensor(m);
}
