// EXT_mesh_gpu_instancing (SimpleInstancing: 125 cubes) against transforms built here with glm
// from the file's accessors, and scene selection (MultipleScenes: the file's default is scene 1).
#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf_hostile.h"
#include "gltf_reference_reader.h"
#include "obscura/io/gltf_loader.h"
#include "test_paths.h"

namespace obscura::test {
namespace {

GltfLoadOptions scene_choice(const std::string& scene) {
  GltfLoadOptions o;
  o.scene = scene;
  return o;
}

TEST(GltfGpuInstancing, SimpleInstancingHasOneInstancePerEntryWithItsTrs) {
  const std::string path = data_path("gltf/SimpleInstancing/SimpleInstancing.glb");
  ReferenceGltf f(path);
  const nlohmann::json& attributes =
      f.json["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
  std::vector<float> t = f.floats(attributes["TRANSLATION"]);
  std::vector<float> r = f.floats(attributes["ROTATION"]);
  std::vector<float> s = f.floats(attributes["SCALE"]);
  ASSERT_EQ(t.size(), 125u * 3);

  Scene scene = load_gltf(path);
  ASSERT_EQ(scene.instances.size(), 125u);
  EXPECT_EQ(scene.meshes.size(), 1u);  // one cube, shared by all
  for (size_t i = 0; i < 125; ++i) {
    glm::dquat q(r[4 * i + 3], r[4 * i], r[4 * i + 1], r[4 * i + 2]);
    glm::dmat4 expected =
        glm::translate(glm::dmat4(1), glm::dvec3(t[3 * i], t[3 * i + 1], t[3 * i + 2])) *
        glm::mat4_cast(glm::normalize(q)) *
        glm::scale(glm::dmat4(1), glm::dvec3(s[3 * i], s[3 * i + 1], s[3 * i + 2]));
    const Matrix4& ours = scene.instances[i].world_from_object.matrix();
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col)
        EXPECT_NEAR(ours.m[row][col], expected[col][row], 1e-6) << "instance " << i;
  }
  for (const std::string& w : scene.warnings)
    EXPECT_EQ(w.find("EXT_mesh_gpu_instancing"), std::string::npos) << w;
}

class GltfGpuInstancingErrors : public GltfHostile {};

TEST_F(GltfGpuInstancingErrors, AttributesOfDifferentLengthsAreAnError) {
  json doc = triangle();
  int three = add_accessor(
      doc, {{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  int two = add_accessor(
      doc, {{"bufferView", 2}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}});
  doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"TRANSLATION", three},
                                                                            {"SCALE", two}};
  expect_error(doc, "instancing.gltf",
               {"nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.SCALE",
                "2 elements where the other attributes have 3"});
}

class GltfScenes : public testing::Test {
 protected:
  std::string path = data_path("gltf/MultipleScenes/MultipleScenes.gltf");
  // MultipleScenes: scene 0 shows a triangle (1 triangle), scene 1 a square (2).
  static size_t triangles(const Scene& scene) { return scene.stats().triangles; }
  // The same file with its scenes named, read with its buffers beside it.
  Scene named(const std::string& choice) {
    nlohmann::json doc = ReferenceGltf(path).json;
    doc["scenes"][0]["name"] = "triangle";
    doc["scenes"][1]["name"] = "square";
    std::string text = doc.dump();
    return load_gltf_bytes(std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()),
                           "named.gltf", data_path("gltf/MultipleScenes"), scene_choice(choice));
  }
};

TEST_F(GltfScenes, DefaultIsTheFilesSceneAndAnIndexSelects) {
  ASSERT_EQ(ReferenceGltf(path).json["scene"], 1);
  EXPECT_EQ(triangles(load_gltf(path)), 2u);
  EXPECT_EQ(triangles(load_gltf(path, scene_choice("0"))), 1u);
  EXPECT_EQ(triangles(load_gltf(path, scene_choice("1"))), 2u);
  for (const std::string& w : load_gltf(path).warnings)
    EXPECT_EQ(w.find("scenes"), std::string::npos) << w;
}

TEST_F(GltfScenes, ANameSelects) {
  EXPECT_EQ(triangles(named("triangle")), 1u);
  EXPECT_EQ(triangles(named("square")), 2u);
}

TEST_F(GltfScenes, AnUnknownSceneListsTheAvailableOnes) {
  for (std::string choice : {"2", "circle"}) {
    try {
      named(choice);
      ADD_FAILURE() << choice;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr("--gltf-scene " + choice + ": no such scene"));
      EXPECT_THAT(e.what(), testing::HasSubstr("the file has 2: 0 'triangle', 1 'square'"));
    }
  }
}

TEST_F(GltfScenes, TheCommandLineSelectsAndRefusesUnknownScenes) {
  CommandResult ok = run_cli("info '" + path + "' --gltf-scene 0");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_THAT(ok.output, testing::HasSubstr("triangles    1 rendered"));
  CommandResult bad = run_cli("info '" + path + "' --gltf-scene 7");
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  EXPECT_THAT(bad.output, testing::HasSubstr("no such scene (the file has 2: 0, 1)"));
  CommandResult not_gltf = run_cli("info cornell-box --gltf-scene 1");
  EXPECT_EQ(not_gltf.exit_code, 1) << not_gltf.output;
  EXPECT_THAT(not_gltf.output, testing::HasSubstr("applies to glTF files"));
}

}  // namespace
}  // namespace obscura::test
