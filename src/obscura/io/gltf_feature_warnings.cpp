#include "obscura/io/gltf_feature_warnings.h"

#include <tiny_gltf.h>

namespace obscura {

namespace {

// Collects the elements that use one feature and words them as a single warning.
class Uses {
 public:
  void add(const std::string& element) {
    if (++count_ <= kNamed) named_ += (named_.empty() ? "" : ", ") + element;
  }
  void warn(const std::string& file, const std::string& feature, const std::string& instead,
            std::vector<std::string>& warnings) const {
    if (count_ == 0) return;
    std::string who = named_;
    if (count_ > kNamed) who += " and " + std::to_string(count_ - kNamed) + " more";
    warnings.push_back(file + ": " + feature + " is not supported yet (" + who + "); " + instead);
  }

 private:
  static constexpr size_t kNamed = 3;
  size_t count_ = 0;
  std::string named_;
};

std::string material_name(const tinygltf::Model& model, size_t i) {
  const std::string& name = model.materials[i].name;
  return "materials[" + std::to_string(i) + "]" + (name.empty() ? "" : " '" + name + "'");
}

}  // namespace

void warn_unapplied_gltf_features(const tinygltf::Model& model, const std::string& file,
                                  std::vector<std::string>& warnings) {
  Uses texcoord;
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& m = model.materials[i];
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    for (int set :
         {pbr.baseColorTexture.texCoord, pbr.metallicRoughnessTexture.texCoord,
          m.normalTexture.texCoord, m.occlusionTexture.texCoord, m.emissiveTexture.texCoord})
      if (set > 1) {
        texcoord.add(material_name(model, i));
        break;
      }
  }
  // TEXCOORD_0 and TEXCOORD_1 are kept (Mesh::uv_set), as glTF asks of every client.
  texcoord.warn(file, "a texture on TEXCOORD_2 or above", "sampled with TEXCOORD_0 instead",
                warnings);

  Uses other_targets;
  for (size_t i = 0; i < model.meshes.size(); ++i)
    for (const tinygltf::Primitive& p : model.meshes[i].primitives) {
      bool other = false;
      for (const auto& target : p.targets)
        for (const auto& [attribute, accessor] : target)
          other =
              other || (attribute != "POSITION" && attribute != "NORMAL" && attribute != "TANGENT");
      if (other) {
        other_targets.add("meshes[" + std::to_string(i) + "]" +
                          (model.meshes[i].name.empty() ? "" : " '" + model.meshes[i].name + "'"));
        break;
      }
    }
  other_targets.warn(file, "morph targets of TEXCOORD_n or COLOR_n",
                     "those attributes keep their base values", warnings);
}

}  // namespace obscura
