// ground_truth(): the exact per-pixel-centre channels `obscura render --ground-truth` writes
// (docs/ground_truth.md) as numpy arrays by layer — depth, range, position, normals, ids,
// forward and backward optical flow and time — from either renderer's visibility, with the GIL
// released while it renders and Ctrl-C stopping it (KeyboardInterrupt).
#include <pybind11/stl.h>

#include <algorithm>
#include <map>

#include "arrays.h"
#include "bindings.h"
#include "interruptible.h"
#include "obscura/math/error.h"
#include "obscura/render/ground_truth_frame.h"

namespace obscura::python {

namespace {

// "flow.forward.X" → ("flow.forward", "X"); "Z" → ("Z", "Z").
std::pair<std::string, std::string> layer_of(const std::string& channel) {
  const size_t dot = channel.rfind('.');
  if (dot == std::string::npos) return {channel, channel};
  return {channel.substr(0, dot), channel.substr(dot + 1)};
}

py::dict ground_truth_py(const Scene& scene, std::optional<Camera> camera,
                         const std::string& renderer,
                         std::optional<std::pair<double, double>> flow_times) {
  const std::optional<Renderer> kind = parse_renderer(renderer);
  if (!kind)
    throw py::value_error("renderer: expected " + renderer_names() + ", got '" + renderer + "'");
  // The GIL is free while the frame renders and another Python thread may change `scene`: the
  // render works on a copy taken here, with the GIL held.
  const Scene snapshot = scene;
  const Camera& view = camera ? *camera : snapshot.camera;
  const GroundTruthTimes times = flow_times
                                     ? GroundTruthTimes{flow_times->first, flow_times->second}
                                     : default_ground_truth_times(view);
  Image image;
  run_interruptible([&](const std::atomic<bool>& cancel) {
    view.validate();
    image = render_ground_truth_frame(snapshot, view, {.renderer = *kind, .cancel = &cancel}, times)
                .image();
  });
  // Channels grouped by layer, in the file's order: one (H, W, C) array each.
  std::vector<std::string> layers;
  std::map<std::string, std::vector<int>> channels;
  for (int c = 0; c < image.channels; ++c) {
    const std::string layer = layer_of(image.channel_names[size_t(c)]).first;
    if (!channels.count(layer)) layers.push_back(layer);
    channels[layer].push_back(c);
  }
  py::dict out;
  for (const std::string& layer : layers) {
    const std::vector<int>& picked = channels[layer];
    Image part(image.width, image.height, int(picked.size()));
    for (int p : picked)
      part.channel_names.push_back(layer_of(image.channel_names[size_t(p)]).second);
    const size_t pixels = size_t(image.width) * image.height;
    for (size_t i = 0; i < pixels; ++i)
      for (size_t k = 0; k < picked.size(); ++k)
        part.data[i * picked.size() + k] = image.data[i * image.channels + picked[k]];
    out[py::str(layer)] = image_to_array(std::move(part));
  }
  out["times"] = py::make_tuple(times.first_s, times.second_s);
  return out;
}

}  // namespace

void bind_ground_truth(py::module_& m) {
  m.def("ground_truth", &ground_truth_py, py::arg("scene"), py::arg("camera") = py::none(),
        py::kw_only(), py::arg("renderer") = "path", py::arg("flow_times") = py::none(),
        "The ground truth `obscura render --ground-truth` writes (docs/ground_truth.md), as a "
        "dict of float32 (H, W, C) arrays by layer: 'Z' (depth along the optical axis, m), "
        "'range', 'P' (world position), 'N' and 'Ng' (shading and geometric normals), "
        "'instance', 'material' (exact integers, -1: nothing), 'flow.forward' and "
        "'flow.backward' (pixels), 'time' (s); and 'times', the pair the flow spans. renderer: "
        "whose visibility ('path', 'whitted', 'direct': one ray per pixel centre; 'raster': the "
        "z-buffer at the pixel centre); flow_times: (A, B) in seconds as --flow-times (default: "
        "the shutter's open and close). Bit for bit the CLI's file's channels.");
}

}  // namespace obscura::python
