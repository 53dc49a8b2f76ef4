// Which of a glTF file's animations plays (`--gltf-animation N|NAME`): a triangle's node moved by
// two animations, "Up" and "Right", each one unit over one second.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "gltf_hostile.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/math/error.h"
#include "run_command.h"

namespace obscura {
namespace {

using nlohmann::json;

json two_animations() {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const float times[2] = {0, 1};
  const float up[6] = {0, 0, 0, 0, 1, 0}, right[6] = {0, 0, 0, 1, 0, 0};
  std::vector<uint8_t> bytes(36 + 8 + 24 + 24);
  std::memcpy(bytes.data(), positions, 36);
  std::memcpy(bytes.data() + 36, times, 8);
  std::memcpy(bytes.data() + 44, up, 24);
  std::memcpy(bytes.data() + 68, right, 24);
  auto view = [](int offset, int length) {
    return json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
  };
  auto sampler = [](int output) {
    return json::array({{{"input", 1}, {"output", output}, {"interpolation", "LINEAR"}}});
  };
  auto channel =
      json::array({{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}});
  return {
      {"asset", {{"version", "2.0"}}},
      {"buffers",
       {{{"byteLength", bytes.size()},
         {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}}},
      {"bufferViews", {view(0, 36), view(36, 8), view(44, 24), view(68, 24)}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 3},
         {"type", "VEC3"},
         {"min", {0, 0, 0}},
         {"max", {1, 1, 0}}},
        {{"bufferView", 1},
         {"componentType", 5126},
         {"count", 2},
         {"type", "SCALAR"},
         {"min", {0}},
         {"max", {1}}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}},
        {{"bufferView", 3}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"animations",
       {{{"name", "Up"}, {"samplers", sampler(2)}, {"channels", channel}},
        {{"name", "Right"}, {"samplers", sampler(3)}, {"channels", channel}}}},
  };
}

Scene load(const std::string& animation) {
  GltfLoadOptions options;
  options.animation = animation;
  return test::load_gltf_json(two_animations(), options, "two.gltf");
}

// Where the node's origin is at the end of the animation.
Point3d end_position(const Scene& scene) {
  EXPECT_EQ(scene.instances.size(), 1u);
  EXPECT_TRUE(scene.instances[0].animated());
  return scene.instances[0].motion.back().world_from_object(Point3d(0, 0, 0));
}

TEST(GltfAnimationChoice, TheFirstPlaysByDefaultAndAWarningNamesTheOthers) {
  Scene scene = load("");
  EXPECT_NEAR(end_position(scene).y, 1, 1e-9);
  bool named = false;
  for (const std::string& w : scene.warnings)
    named = named || (w.find("0 'Up', 1 'Right'") != std::string::npos &&
                      w.find("--gltf-animation") != std::string::npos);
  EXPECT_TRUE(named) << ::testing::PrintToString(scene.warnings);
}

TEST(GltfAnimationChoice, AnIndexOrANameChooses) {
  for (const char* choice : {"1", "Right"}) {
    Scene scene = load(choice);
    Point3d end = end_position(scene);
    EXPECT_NEAR(end.x, 1, 1e-9) << choice;
    EXPECT_NEAR(end.y, 0, 1e-9) << choice;
    EXPECT_TRUE(scene.warnings.empty()) << ::testing::PrintToString(scene.warnings);
  }
  EXPECT_NEAR(end_position(load("Up")).y, 1, 1e-9);
}

TEST(GltfAnimationChoice, AnUnknownOneListsTheAvailable) {
  for (const char* choice : {"2", "Walk"}) {
    try {
      load(choice);
      ADD_FAILURE() << choice;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("--gltf-animation ") + choice +
                                           ": no such animation (the file has 2: 0 'Up', 1 "
                                           "'Right')"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(GltfAnimationChoice, TheCommandLineRefusesItForOtherFiles) {
  test::CommandResult result = test::run_cli("info cornell-box --gltf-animation 1");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("--gltf-animation 1 applies to glTF files"), std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace obscura
