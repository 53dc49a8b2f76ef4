#include "obscura/scene/material_variants.h"

#include <algorithm>

#include "obscura/math/error.h"

namespace obscura {

void select_material_variant(Scene& scene, const std::string& name) {
  const std::vector<std::string>& names = scene.material_variants;
  auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end()) {
    std::string known;
    for (const std::string& n : names) {
      if (!known.empty()) known += ", ";
      known.append("'").append(n).append("'");
    }
    throw Error("material variant '" + name + "'",
                names.empty() ? "the scene has no material variants (glTF KHR_materials_variants)"
                              : "not in the scene; its variants are " + known);
  }
  const auto variant = uint32_t(found - names.begin());
  for (Instance& instance : scene.instances)
    for (auto [v, material] : instance.variant_materials)
      if (v == variant) instance.material = int32_t(material);
}

}  // namespace obscura
