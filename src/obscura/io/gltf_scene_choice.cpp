#include "obscura/io/gltf_scene_choice.h"

#include <tiny_gltf.h>

#include <algorithm>

#include "obscura/math/error.h"

namespace obscura {

namespace {

std::string available(const tinygltf::Model& model) {
  if (model.scenes.empty()) return "the file has no scenes";
  std::string list;
  for (size_t i = 0; i < model.scenes.size() && i < 32; ++i) {
    list += (list.empty() ? "" : ", ") + std::to_string(i);
    if (!model.scenes[i].name.empty()) list += " '" + model.scenes[i].name + "'";
  }
  if (model.scenes.size() > 32) list += ", …";
  return "the file has " + std::to_string(model.scenes.size()) + ": " + list;
}

}  // namespace

int choose_gltf_scene(const tinygltf::Model& model, const std::string& choice,
                      const std::string& file) {
  if (choice.empty()) {
    int index = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (!model.scenes.empty() && size_t(index) >= model.scenes.size())
      throw Error(file + ": scene", "scene index " + std::to_string(index) + " is out of range (" +
                                        available(model) + ")");
    return index;
  }
  const bool digits =
      choice.size() <= 9 && std::all_of(choice.begin(), choice.end(),
                                        [](unsigned char c) { return c >= '0' && c <= '9'; });
  if (digits) {
    size_t index = std::stoul(choice);
    if (index < model.scenes.size()) return int(index);
  } else {
    for (size_t i = 0; i < model.scenes.size(); ++i)
      if (model.scenes[i].name == choice) return int(i);
  }
  throw Error(file, "--gltf-scene " + choice + ": no such scene (" + available(model) + ")");
}

}  // namespace obscura
