#include "obscura/io/gltf_scene_choice.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <vector>

#include "obscura/math/error.h"

namespace obscura {

namespace {

// "the file has 3: 0 'Survey', 1 'Walk', 2 'Run'" for elements with a `name`.
template <class Element>
std::string available(const std::vector<Element>& elements, const char* what) {
  if (elements.empty()) return std::string("the file has no ") + what;
  std::string list;
  for (size_t i = 0; i < elements.size() && i < 32; ++i) {
    list += (list.empty() ? "" : ", ") + std::to_string(i);
    if (!elements[i].name.empty()) list += " '" + elements[i].name + "'";
  }
  if (elements.size() > 32) list += ", …";
  return "the file has " + std::to_string(elements.size()) + ": " + list;
}

// The element `choice` names: a decimal index (a name made of digits is taken as an index) or
// a name; −1 when none matches.
template <class Element>
int find_by_index_or_name(const std::vector<Element>& elements, const std::string& choice) {
  const bool digits =
      choice.size() <= 9 && std::all_of(choice.begin(), choice.end(),
                                        [](unsigned char c) { return c >= '0' && c <= '9'; });
  if (digits) {
    size_t index = std::stoul(choice);
    return index < elements.size() ? int(index) : -1;
  }
  for (size_t i = 0; i < elements.size(); ++i)
    if (elements[i].name == choice) return int(i);
  return -1;
}

}  // namespace

int choose_gltf_scene(const tinygltf::Model& model, const std::string& choice,
                      const std::string& file) {
  if (choice.empty()) {
    int index = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (!model.scenes.empty() && size_t(index) >= model.scenes.size())
      throw Error(file + ": scene", "scene index " + std::to_string(index) + " is out of range (" +
                                        available(model.scenes, "scenes") + ")");
    return index;
  }
  int index = find_by_index_or_name(model.scenes, choice);
  if (index < 0)
    throw Error(file, "--gltf-scene " + choice + ": no such scene (" +
                          available(model.scenes, "scenes") + ")");
  return index;
}

int choose_gltf_animation(const tinygltf::Model& model, const std::string& choice,
                          const std::string& file, std::vector<std::string>& warnings) {
  if (choice.empty()) {
    if (model.animations.size() > 1)
      warnings.push_back(file + ": plays animations[0], the first of " +
                         available(model.animations, "animations").substr(13) +
                         "; choose another with --gltf-animation N|NAME");
    return model.animations.empty() ? -1 : 0;
  }
  int index = find_by_index_or_name(model.animations, choice);
  if (index < 0)
    throw Error(file, "--gltf-animation " + choice + ": no such animation (" +
                          available(model.animations, "animations") + ")");
  return index;
}

}  // namespace obscura
