// Material variants (glTF KHR_materials_variants): one file, several looks (a shoe in three
// colours), chosen by name. The loader fills Scene::material_variants and each instance's
// variant_materials; without a selection, instances keep the file's default materials.
#pragma once

#include <string>

#include "obscura/scene/scene.h"

namespace obscura {

// Draws every instance that names a material for variant `name` with that material; the others
// keep theirs. Throws obscura::Error listing the scene's variant names when `name` is not one.
void select_material_variant(Scene& scene, const std::string& name);

}  // namespace obscura
