// Motion keys from Python, as scene files give them: a camera's pose and an instance's placement
// at several times, interpolated between keys (translation and scale linearly, rotation by
// slerp) over the shutter — what motion blur, optical flow and a rolling shutter see.
#include <pybind11/stl.h>

#include <utility>
#include <vector>

#include "arrays.h"
#include "bindings.h"
#include "obscura/camera/animated_transform.h"
#include "obscura/scene/scene.h"

namespace obscura::python {

namespace {

using PyKeys = std::vector<std::pair<double, py::object>>;
using KeyList = std::vector<std::pair<double, py::array_t<double>>>;

// Checked as AnimatedTransform checks them: at least one key, times strictly increasing and
// finite, each a translation · rotation · scale (obscura.Error naming the key otherwise).
AnimatedTransform animated(const PyKeys& keys, const char* what) {
  if (keys.empty()) throw py::value_error(std::string(what) + ": expected at least one key");
  std::vector<AnimatedTransform::Key> converted;
  for (const auto& [time, matrix] : keys)
    converted.push_back({time, Transform(array_to_matrix(matrix, what))});
  return AnimatedTransform(std::move(converted));
}

KeyList key_list(const std::vector<AnimatedTransform::Key>& keys) {
  KeyList out;
  for (const AnimatedTransform::Key& key : keys)
    out.emplace_back(key.time_s, matrix_to_array(key.transform.matrix()));
  return out;
}

Instance& instance_at(Scene& scene, size_t index) {
  if (index >= scene.instances.size())
    throw py::index_error("instance " + std::to_string(index) + ": the scene has " +
                          std::to_string(scene.instances.size()) + " instances");
  return scene.instances[index];
}

}  // namespace

void bind_motion(py::module_& m) {
  auto camera = py::reinterpret_borrow<py::class_<Camera>>(m.attr("Camera"));
  camera.def(
      "set_motion",
      [](Camera& c, const PyKeys& keys) { c.world_from_camera = animated(keys, "set_motion"); },
      py::arg("keys"),
      "Animates the camera: keys is a list of (time in seconds, 4x4 world_from_camera), times "
      "increasing, each a translation, rotation and scale. The renderers see the pose at each "
      "sample's time within the shutter (motion blur, rolling shutter, optical flow).");
  camera.def_property_readonly(
      "motion", [](const Camera& c) { return key_list(c.world_from_camera.keys()); },
      "The pose's keys as (time, 4x4 world_from_camera): one for a still camera.");

  auto scene = py::reinterpret_borrow<py::class_<Scene>>(m.attr("Scene"));
  scene.def_property_readonly(
      "instance_count", [](const Scene& s) { return s.instances.size(); },
      "How many instances place meshes in the world (add_mesh adds one per mesh).");
  scene.def(
      "set_motion",
      [](Scene& s, size_t instance, const PyKeys& keys) {
        Instance& placed = instance_at(s, instance);
        const AnimatedTransform motion = animated(keys, "set_motion");
        placed.motion.clear();
        if (motion.is_animated())
          for (const AnimatedTransform::Key& key : motion.keys())
            placed.motion.push_back({key.time_s, key.transform});
        placed.world_from_object = motion.at(0);  // the pose at time 0, as loaders set it
      },
      py::arg("instance"), py::arg("keys"),
      "Moves an instance (its index: add_mesh's return for a scene built with add_mesh): keys "
      "is a list of (time in seconds, 4x4 world_from_object), times increasing, each a "
      "translation, rotation and scale; one key places it still.");
  scene.def(
      "motion",
      [](Scene& s, size_t instance) {
        const Instance& placed = instance_at(s, instance);
        if (!placed.animated())
          return KeyList{{0.0, matrix_to_array(placed.world_from_object.matrix())}};
        KeyList out;
        for (const TransformKey& key : placed.motion)
          out.emplace_back(key.time_seconds, matrix_to_array(key.world_from_object.matrix()));
        return out;
      },
      py::arg("instance"),
      "An instance's keys as (time, 4x4 world_from_object): one for a still instance.");
}

}  // namespace obscura::python
