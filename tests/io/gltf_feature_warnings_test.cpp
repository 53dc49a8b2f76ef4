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

TEST_F(GltfFeatureWarnings, AlphaModesNeedNoWarning) {
  // Both renderers apply MASK and BLEND (tests/raster/alpha_coverage_raster_test.cpp).
  json doc = triangle();
  doc["materials"] = {{{"name", "leaves"}, {"alphaMode", "MASK"}},
                      {{"name", "glass"}, {"alphaMode", "BLEND"}}};
  doc["meshes"][0]["primitives"][0]["material"] = 0;
  EXPECT_TRUE(warnings_of(doc).empty());
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
  // Skins, morph targets and scenes are applied: without an animation, nothing to warn about.
  EXPECT_FALSE(any_contains(w, "skin"));
  EXPECT_FALSE(any_contains(w, "morph"));
  EXPECT_TRUE(any_contains(w, "TEXCOORD_2 or above is not supported yet (materials[0])"));
  EXPECT_FALSE(any_contains(w, "scenes"));
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

TEST_F(GltfFeatureWarnings, UvAndColorMorphTargetsAreNamed) {
  json doc = triangle();
  // A TEXCOORD_0 morph target (the triangle's positions stand in for its deltas' bytes).
  doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", 0}, {"TEXCOORD_0", 0}}};
  doc["meshes"][0]["name"] = "blob";
  doc["meshes"][0]["weights"] = {0.0};
  int times = add_accessor(
      doc, {{"bufferView", 2}, {"componentType", 5126}, {"count", 1}, {"type", "SCALAR"}});
  json channel = {{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}};
  json sampler = {{"input", times}, {"output", times}};
  doc["animations"] = json::array({{{"channels", {channel}}, {"samplers", {sampler}}}});
  std::vector<std::string> w = warnings_of(doc);
  EXPECT_TRUE(any_contains(w,
                           "morph targets of TEXCOORD_n or COLOR_n is not supported yet "
                           "(meshes[0] 'blob')"));
  // An animated morph is applied (and motion-blurred): nothing else to say about it.
  EXPECT_EQ(w.size(), 1u);
}

TEST_F(GltfFeatureWarnings, ManyUsesAreCountedNotListed) {
  json doc = triangle();
  doc["materials"] = json::array();
  for (int i = 0; i < 5; ++i)
    doc["materials"].push_back({{"emissiveTexture", {{"index", 0}, {"texCoord", 2}}}});
  doc["textures"] = {{{"source", 0}}};
  doc["images"] = {{{"uri", "missing.png"}}};
  std::vector<std::string> w = warnings_of(doc);
  EXPECT_TRUE(any_contains(w, "materials[0], materials[1], materials[2] and 2 more"));
}

}  // namespace
}  // namespace obscura::test
