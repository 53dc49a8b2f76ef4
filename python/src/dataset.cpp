// render_dataset(): `obscura dataset` from Python — the views of render/dataset_views.h around a
// resolved camera, rendered and written by the library's dataset writer (render/dataset.h), the
// same files the command line writes.
#include <pybind11/stl.h>

#include "bindings.h"
#include "interruptible.h"
#include "obscura/render/dataset.h"
#include "obscura/render/render_session.h"
#include "render_call.h"

namespace obscura::python {

namespace {

py::dict render_dataset_py(const Scene& scene, const std::string& views, const std::string& output,
                           std::optional<Camera> camera, const std::string& renderer,
                           std::optional<int> spp, std::optional<uint64_t> seed, bool ground_truth,
                           bool aovs, const std::string& image_format,
                           const std::vector<std::string>& formats) {
  // A copy: another Python thread may change `scene` while the GIL is free.
  auto copy = std::make_shared<const Scene>(scene);
  DatasetPlan plan;
  plan.directory = output;
  RenderRequest request{
      .renderer = renderer, .frame = {.samples_per_pixel = spp, .seed = seed}, .aovs = aovs};
  plan.settings = frame_settings(request, copy->render, nullptr);
  plan.outputs.image_format = image_format;
  plan.outputs.ground_truth = ground_truth;
  plan.outputs.aovs = aovs;
  plan.outputs.formats = formats;
  DatasetReport report;
  run_interruptible([&](const std::atomic<bool>& cancel) {
    // Ctrl-C stops the view in progress (written views stay: a later call resumes).
    plan.settings.cancel = &cancel;
    const Camera base = camera ? *camera : copy->camera;
    plan.views = dataset_views(*copy, base, views);
    RenderSession session(*copy);
    report = render_dataset(session, plan);
  });
  for (const std::string& warning : report.warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
  py::dict out;
  py::list names, images;
  for (size_t i = 0; i < plan.views.size(); ++i) {
    names.append(plan.views[i].name);
    images.append(dataset_image_path(plan, i));
  }
  out["views"] = names;
  out["images"] = images;
  out["rendered"] = report.rendered;
  out["skipped"] = report.skipped;
  out["warnings"] = report.warnings;
  return out;
}

}  // namespace

void bind_dataset(py::module_& m) {
  const py::none none;
  m.def("render_dataset", &render_dataset_py, py::arg("scene"), py::arg("views"), py::arg("output"),
        py::kw_only(), py::arg("camera") = none, py::arg("renderer") = "path",
        py::arg("spp") = none, py::arg("seed") = none, py::arg("ground_truth") = false,
        py::arg("aovs") = false, py::arg("image_format") = "png",
        py::arg("formats") = std::vector<std::string>{"colmap", "nerf", "opencv"},
        "Renders a calibrated dataset as `obscura dataset SCENE --views VIEWS -o OUTPUT` does: "
        "views 'orbit:N[:ELEVATION]', 'sphere:N', 'path:N:FILE' or 'cameras' (docs/camera.md, "
        "\"Datasets\") around `camera` (a resolve_camera() result: its projection, lens and film "
        "for every view; default the scene's camera), each view's image "
        "(images/view_0000.png, or image_format), with ground_truth=True its ground truth "
        "(ground_truth/view_0000.exr, flow between consecutive views), with aovs=True its AOVs, "
        "and the calibration files `formats` names: one COLMAP model (sparse/0/), one "
        "transforms.json, an OpenCV file per view (opencv/). Views whose files are already "
        "there are skipped (resume). What a format cannot hold (a fisheye's field limit) is a "
        "UserWarning. Returns {'views', 'images', 'rendered', 'skipped', 'warnings'}.");
}

}  // namespace obscura::python
