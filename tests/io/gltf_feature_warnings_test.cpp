// Core glTF features the importer does not apply yet are each named in a warning, never dropped
// silently; a file without them gets none of these warnings.
#include "gltf_hostile.h"

namespace obscura::test {
namespace {

using testing::HasSubstr;

class GltfFeatureWarnings : public GltfHostile {
 protected:
  std::vector<std::string> warnings_of(const json& doc) {
    return load_gltf(write("features.gltf", doc)).warnings;
  }
  static bool any_contains(const std::vector<std::string>& warnings, const std::string& text) {
    for (const std::string& w : warnings)
      if (w.find(text) != std::string::npos) return true;
    return false;
  }
};

TEST_F(GltfFeatureWarnings, APlainTriangleHasNone) {
  EXPECT_TRUE(warnings_of(triangle()).empty());
}

TEST_F(GltfFeatureWarnings, AlphaModesAreNamedWithTheirMaterials) {
  json doc = triangle();
  doc["materials"] = {{{"name", "leaves"}, {"alphaMode", "MASK"}},
                      {{"name", "glass"}, {"alphaMode", "BLEND"}},
                      {{"name", "plain"}, {"alphaMode", "OPAQUE"}}};
  doc["meshes"][0]["primitives"][0]["material"] = 0;
  std::vector<std::string> w = warnings_of(doc);
  EXPECT_TRUE(any_contains(
      w, "alphaMode MASK in the rasterizer is not supported yet (materials[0] 'leaves')"));
  EXPECT_TRUE(any_contains(
      w, "alphaMode BLEND in the rasterizer is not supported yet (materials[1] 'glass')"));
  EXPECT_FALSE(any_contains(w, "plain"));
}

TEST_F(GltfFeatureWarnings, SkinsMorphTargetsOtherUvSetsAndScenes) {
  json doc = triangle();
  doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", 0}}};
  doc["meshes"][0]["name"] = "blob";
  doc["nodes"].push_back({{"name", "joint"}});
  doc["scenes"][0]["nodes"].push_back(1);
  // (tinygltf insists on inverseBindMatrices, which the specification makes optional.)
  int matrices = add_accessor(doc, {{"bufferView", 2},
                                    {"byteOffset", 64},
                                    {"componentType", 5126},
                                    {"count", 1},
                                    {"type", "MAT4"}});
  doc["skins"] = {{{"joints", {1}}, {"name", "rig"}, {"inverseBindMatrices", matrices}}};
  doc["scenes"].push_back({{"nodes", json::array()}});
  doc["materials"] = {
      {{"emissiveTexture", {{"index", 0}, {"texCoord", 2}}}, {"normalTexture", {{"index", 0}}}}};
  doc["textures"] = {{{"source", 0}}};
  doc["images"] = {{{"uri", "missing.png"}}};
  std::vector<std::string> w = warnings_of(doc);
  EXPECT_TRUE(any_contains(w, "skinning is not supported yet (skins[0] 'rig')"));
  EXPECT_TRUE(any_contains(w, "morph targets is not supported yet (meshes[0] 'blob')"));
  EXPECT_TRUE(any_contains(w, "TEXCOORD_2 or above is not supported yet (materials[0])"));
  EXPECT_TRUE(any_contains(w, "the file has 2 scenes; only scenes[0]"));
  // Normal maps and TEXCOORD_1 are applied: no warning names them.
  EXPECT_FALSE(any_contains(w, "normalTexture"));
  EXPECT_FALSE(any_contains(w, "TEXCOORD_1"));
}

TEST_F(GltfFeatureWarnings, TheSecondUvSetAndNormalMapsAreApplied) {
  json doc = triangle();
  doc["materials"] = {{{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}},
                       {"normalTexture", {{"index", 0}, {"texCoord", 1}}}}};
  doc["textures"] = {{{"source", 0}}};
  doc["images"] = {{{"uri", "missing.png"}}};
  EXPECT_FALSE(any_contains(warnings_of(doc), "is not supported yet"));
}

TEST_F(GltfFeatureWarnings, ManyUsesAreCountedNotListed) {
  json doc = triangle();
  doc["materials"] = json::array();
  for (int i = 0; i < 5; ++i) doc["materials"].push_back({{"alphaMode", "MASK"}});
  std::vector<std::string> w = warnings_of(doc);
  EXPECT_TRUE(any_contains(w, "materials[0], materials[1], materials[2] and 2 more"));
}

}  // namespace
}  // namespace obscura::test
