// Scenes built into Obscura, so that the tool renders something useful with no input file.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "obscura/scene/scene.h"

namespace obscura {

// The names of the built-in scenes; the first is the default.
std::vector<std::string> builtin_scene_names();
bool is_builtin_scene(std::string_view name);
// Throws obscura::Error listing the known names when `name` is not one of them.
Scene make_builtin_scene(std::string_view name);

// The original Cornell box, with the dimensions and camera measured and published by the
// Cornell Program of Computer Graphics, converted from millimetres to metres.
Scene make_cornell_box();

}  // namespace obscura
