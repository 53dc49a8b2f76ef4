#include "obscura/scene/builtin_scenes.h"

#include "obscura/math/error.h"

namespace obscura {

std::vector<std::string> builtin_scene_names() {
  return {"cornell-box"};
}

bool is_builtin_scene(std::string_view name) {
  for (const std::string& n : builtin_scene_names())
    if (n == name) return true;
  return false;
}

Scene make_builtin_scene(std::string_view name) {
  if (name == "cornell-box") return make_cornell_box();
  std::string known;
  for (const std::string& n : builtin_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw Error("scene '" + std::string(name) + "'",
              "not a built-in scene; built-in scenes: " + known);
}

}  // namespace obscura
