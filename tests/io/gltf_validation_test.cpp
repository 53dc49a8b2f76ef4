// glTF files that are invalid by the specification or hostile in their structure (issue 12 items
// 2, 6 and 8): animation samplers, buffers that are directories or malformed, the asset and GLB
// versions, required extensions, node transforms and hierarchies, punctual lights, and images
// that cannot be read (a warning, not an error). Each file is built here from the one-triangle
// document of gltf_hostile.h, broken in one place.
#include <sys/stat.h>

#include <numbers>

#include "io/gltf_hostile.h"
#include "run_command.h"

namespace obscura {
namespace {

using nlohmann::json;
using test::base64;
using test::GltfHostile;
using test::kCount2To62;

// The triangle with node 0 translated by an animation: key times at byte 64, VEC3 values at 128
// of the 648-byte buffer (bufferViews 3 and 4, accessors 2 and 3).
json animated(const std::vector<float>& times, const std::vector<float>& values,
              const std::string& interpolation = "LINEAR") {
  json doc = GltfHostile::triangle();
  std::vector<uint8_t> bytes = GltfHostile::buffer_bytes();
  std::memcpy(bytes.data() + 64, times.data(), times.size() * 4);
  std::memcpy(bytes.data() + 128, values.data(), values.size() * 4);
  GltfHostile::set_buffer(doc, bytes);
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 64}, {"byteLength", 64}});
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 128}, {"byteLength", 256}});
  doc["accessors"].push_back(
      {{"bufferView", 3}, {"componentType", 5126}, {"count", times.size()}, {"type", "SCALAR"}});
  doc["accessors"].push_back(
      {{"bufferView", 4}, {"componentType", 5126}, {"count", values.size() / 3}, {"type", "VEC3"}});
  doc["animations"] = {
      {{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
       {"samplers", {{{"input", 2}, {"output", 3}, {"interpolation", interpolation}}}}}};
  return doc;
}

// --- Animation samplers ---

TEST_F(GltfHostile, AWellFormedAnimationGivesOneKeyPerTime) {
  Scene scene = load_gltf(write("anim.gltf", animated({0, 1}, {0, 0, 0, 2, 0, 0})));
  ASSERT_EQ(scene.instances.size(), 1u);
  ASSERT_EQ(scene.instances[0].motion.size(), 2u);
  EXPECT_DOUBLE_EQ(scene.instances[0].motion[1].time_seconds, 1.0);
}

TEST_F(GltfHostile, AnimationSamplersMustBeConsistent) {
  const float nan = std::nanf("");
  struct Case {
    std::string name;
    json doc;
    std::vector<std::string> expected;
  };
  std::vector<Case> cases = {
      {"counts",
       animated({0, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}),
       {"animations[0].samplers[0]", "input has 2 key times but output has 3 values"}},
      {"cubic",
       animated({0, 1}, {0, 0, 0, 1, 0, 0}, "CUBICSPLINE"),
       {"animations[0].samplers[0]", "expected 6 for CUBICSPLINE"}},
      {"decreasing",
       animated({0, 1, 0.5f}, {0, 0, 0, 1, 0, 0, 2, 0, 0}),
       {"animations[0].samplers[0].input", "key times must increase"}},
      {"equal", animated({0, 1, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}), {"key times must increase"}},
      {"nan-time", animated({0, nan}, {0, 0, 0, 1, 0, 0}), {"key time 1", "not a finite time"}},
      {"negative-time", animated({-1, 0}, {0, 0, 0, 1, 0, 0}), {"key time 0"}},
      {"nan-value",
       animated({0, 1}, {0, 0, 0, nan, 0, 0}),
       {"animations[0].samplers[0].output", "value 1 is not finite"}},
      {"interpolation",
       animated({0, 1}, {0, 0, 0, 1, 0, 0}, "BEZIER"),
       {"interpolation", "BEZIER"}},
  };
  json huge = animated({0, 1}, {0, 0, 0, 1, 0, 0});
  huge["accessors"][2]["count"] = kCount2To62;
  cases.push_back({"huge-input",
                   huge,
                   {"animations[0].samplers[0].input (accessor 2)",
                    "count 4611686018427387904 × stride 4 exceeds bufferView 3 (64 bytes)"}});
  json node = animated({0, 1}, {0, 0, 0, 1, 0, 0});
  node["animations"][0]["channels"][0]["target"]["node"] = 5;
  cases.push_back(
      {"node", node, {"animations[0].channels[0].target.node", "node index 5 is out of range"}});
  json sampler = animated({0, 1}, {0, 0, 0, 1, 0, 0});
  sampler["animations"][0]["channels"][0]["sampler"] = 3;
  cases.push_back({"sampler", sampler, {"channels[0].sampler", "sampler index 3"}});
  json accessor = animated({0, 1}, {0, 0, 0, 1, 0, 0});
  accessor["animations"][0]["samplers"][0]["output"] = 40;
  cases.push_back({"accessor", accessor, {"samplers[0].output", "accessor index 40"}});
  json matrix = animated({0, 1}, {0, 0, 0, 1, 0, 0});
  matrix["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  cases.push_back({"matrix-animated", matrix, {"target.node", "must use TRS"}});
  for (const Case& c : cases) {
    std::vector<std::string> expected = c.expected;
    expected.push_back(c.name + ".gltf");
    expect_error(c.doc, c.name + ".gltf", expected);
  }
}

TEST_F(GltfHostile, ManyInstancesUnderALongAnimationAreBounded) {
  // 1024 keys on a root with 1030 mesh children: each child would get its own 1024 world keys
  // (~270 bytes each); past kMaxWorldKeys (2^20) in all the file is refused instead.
  const int keys = 1024, children = 1030;
  std::vector<float> times(keys), values(3 * keys);
  for (int k = 0; k < keys; ++k) times[k] = 0.01f * float(k), values[3 * k] = 0.001f * float(k);
  std::vector<uint8_t> bytes = GltfHostile::buffer_bytes();
  size_t at = bytes.size();
  bytes.resize(at + 16 * keys);
  std::memcpy(bytes.data() + at, times.data(), 4 * keys);
  std::memcpy(bytes.data() + at + 4 * keys, values.data(), 12 * keys);
  json doc = triangle();
  set_buffer(doc, bytes);
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 4 * keys}});
  doc["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", at + 4 * keys}, {"byteLength", 12 * keys}});
  doc["accessors"].push_back(
      {{"bufferView", 3}, {"componentType", 5126}, {"count", keys}, {"type", "SCALAR"}});
  doc["accessors"].push_back(
      {{"bufferView", 4}, {"componentType", 5126}, {"count", keys}, {"type", "VEC3"}});
  doc["animations"] = {
      {{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
       {"samplers", {{{"input", 2}, {"output", 3}}}}}};
  doc["nodes"] = {{{"children", json::array()}}};
  for (int c = 1; c <= children; ++c) {
    doc["nodes"][0]["children"].push_back(c);
    doc["nodes"].push_back({{"mesh", 0}});
  }
  try {
    load_gltf(write("many-keys.gltf", doc));
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), testing::HasSubstr("many-keys.gltf: nodes["));
    EXPECT_THAT(e.what(), testing::HasSubstr("more than 1048576 transform keys"));
  }
}

// --- Files: buffers that are directories, missing, malformed; the glTF file itself ---

TEST_F(GltfHostile, BufferUrisThatCannotBeReadAreClearErrors) {
  std::filesystem::create_directory(dir + "/data.bin");
  struct Case {
    std::string name, uri;
    std::vector<std::string> expected;
  };
  for (const Case& c : std::vector<Case>{
           {"directory", "data.bin", {"data.bin", "is a directory"}},
           {"missing", "nowhere.bin", {"nowhere.bin", "not found"}},
           {"base64", "data:application/octet-stream;base64,@@@@", {"Failed to decode"}},
           {"short", "data:application/octet-stream;base64,AAAA", {"Failed to decode"}},
       }) {
    json doc = triangle();
    doc["buffers"][0]["uri"] = c.uri;
    std::vector<std::string> expected = c.expected;
    expected.push_back(c.name + ".gltf");
    expect_error(doc, c.name + ".gltf", expected);
  }
}

TEST_F(GltfHostile, TheFileItselfMustBeARegularFile) {
  expect_error(dir, {dir, "is a directory"});
  std::string fifo = dir + "/fifo.gltf";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expect_error(fifo, {"fifo.gltf", "not a regular file"});  // never opened, so never blocks
  std::string zero = dir + "/zero.glb";
  std::filesystem::create_symlink("/dev/zero", zero);
  expect_error(zero, {"zero.glb", "not a regular file"});
  expect_error(write("empty.gltf", std::string()), {"empty.gltf", "empty"});
}

TEST_F(GltfHostile, TheCliReportsABufferDirectoryWithExitOne) {
  std::filesystem::create_directory(dir + "/data.bin");
  json doc = triangle();
  doc["buffers"][0]["uri"] = "data.bin";
  test::CommandResult r = test::run_cli("info " + write("cli-dir.gltf", doc));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, testing::HasSubstr("data.bin"));
  EXPECT_THAT(r.output, testing::Not(testing::HasSubstr("bad_alloc")));
  json huge = triangle();
  huge["accessors"][1]["bufferView"] = 2;
  huge["accessors"][1]["count"] = 2147483647;
  r = test::run_cli("info " + write("cli-indices.gltf", huge));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, testing::HasSubstr("count 2147483647 × stride 2 exceeds bufferView 2"));
}

// --- Versions and extensions ---

// A GLB container around `doc` (JSON chunk only; buffers stay data URIs).
std::string glb(const json& doc, uint32_t version) {
  std::string text = doc.dump();
  while (text.size() % 4) text += ' ';
  std::string out = "glTF";
  auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  u32(version);
  u32(uint32_t(12 + 8 + text.size()));
  u32(uint32_t(text.size()));
  u32(0x4E4F534A);  // "JSON"
  return out + text;
}

TEST_F(GltfHostile, VersionsMustBe2) {
  json doc = triangle();
  EXPECT_NO_THROW(load_gltf(write("ok.glb", glb(doc, 2))));
  expect_error(write("v1.glb", glb(doc, 1)), {"v1.glb", "GLB container version 1"});
  doc["asset"]["version"] = "3.0";
  expect_error(doc, "v3.gltf", {"v3.gltf", "asset.version", "glTF 3.0 is not supported"});
  doc["asset"]["version"] = "two";
  expect_error(doc, "vtext.gltf", {"asset.version", "'two' is not a glTF version"});
  doc["asset"]["version"] = "2.1";  // a later 2.x loads (forward compatible)...
  EXPECT_NO_THROW(load_gltf(write("v21.gltf", doc)));
  doc["asset"]["minVersion"] = "2.1";  // ...unless it says it needs more than 2.0
  expect_error(doc, "min21.gltf", {"min21.gltf", "asset.minVersion", "requires glTF 2.1"});
}

TEST_F(GltfHostile, RequiredExtensionsMustBeSupportedUsedOnesWarnOnce) {
  json doc = triangle();
  doc["extensionsRequired"] = {"MSFT_lod"};
  doc["extensionsUsed"] = {"MSFT_lod"};
  expect_error(doc, "lod.gltf",
               {"lod.gltf", "extensionsRequired[0]", "MSFT_lod", "does not support"});
  json used = triangle();
  used["extensionsUsed"] = {"KHR_texture_transform", "KHR_lights_punctual"};
  json transform = {{"KHR_texture_transform", {{"scale", {2, 2}}}}};
  used["materials"] = {{{"extensions", transform}}, {{"extensions", transform}}};
  used["meshes"][0]["primitives"][0]["material"] = 1;
  Scene scene = load_gltf(write("used.gltf", used));
  EXPECT_EQ(count_warnings(scene, "KHR_texture_transform"), 1);
  EXPECT_EQ(count_warnings(scene, "KHR_lights_punctual"), 0);
  // Metadata (TransmissionTest carries KHR_xmp): nothing to render, nothing to warn about.
  json metadata = triangle();
  metadata["extensionsUsed"] = {"KHR_xmp", "KHR_xmp_json_ld"};
  EXPECT_TRUE(load_gltf(write("xmp.gltf", metadata)).warnings.empty());
}

// --- Nodes ---

TEST_F(GltfHostile, NodeTransformsHaveTheirSpecShapes) {
  struct Case {
    std::string name, key;
    json value;
    std::string expected;
  };
  for (const Case& c : std::vector<Case>{
           {"matrix3", "matrix", {1, 0, 0}, "nodes[0].matrix: has 3 numbers, expected 16"},
           {"translation2", "translation", {1, 0}, "nodes[0].translation: has 2 numbers"},
           {"rotation3", "rotation", {0, 0, 0}, "nodes[0].rotation: has 3 numbers, expected 4"},
           {"scale4", "scale", {1, 1, 1, 1}, "nodes[0].scale: has 4 numbers, expected 3"},
       }) {
    json doc = triangle();
    doc["nodes"][0][c.key] = c.value;
    expect_error(doc, c.name + ".gltf", {c.name + ".gltf", c.expected});
  }
  // (A matrix with translation/rotation/scale as well is invalid too, but tinygltf reads the
  // matrix and drops the rest before Obscura sees the node.)
}

TEST_F(GltfHostile, TheNodeHierarchyIsAForest) {
  struct Case {
    std::string name;
    json nodes, roots;
    std::vector<std::string> expected;
  };
  for (const Case& c : std::vector<Case>{
           {"cycle",
            {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}},
            json::array(),
            {"nodes[0]", "cycle"}},
           {"self", {{{"mesh", 0}, {"children", {0}}}}, {0}, {"nodes[0].children[0]", "own"}},
           {"two-parents",
            {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}},
            {0, 1},
            {"nodes[1].children[0]", "node 2 already has parent node 0"}},
           {"twice-listed",
            {{{"children", {1, 1}}}, {{"mesh", 0}}},
            {0},
            {"nodes[0].children[1]", "already has parent node 0"}},
           {"child-out-of-range",
            {{{"children", {7}}}},
            {0},
            {"nodes[0].children[0]", "node index 7 is out of range"}},
           {"scene-child",
            {{{"children", {1}}}, {{"mesh", 0}}},
            {0, 1},
            {"scenes[0].nodes[1]", "node 1 is a child of node 0"}},
           {"scene-twice", {{{"mesh", 0}}}, {0, 0}, {"scenes[0].nodes[1]", "listed twice"}},
       }) {
    json doc = triangle();
    doc["nodes"] = c.nodes;
    doc["scenes"][0]["nodes"] = c.roots;
    std::vector<std::string> expected = c.expected;
    expected.push_back(c.name + ".gltf");
    expect_error(doc, c.name + ".gltf", expected);
  }
}

TEST_F(GltfHostile, ADeepButValidChainIsNoCycle) {
  json doc = triangle();
  doc["nodes"] = json::array();
  for (int i = 0; i < 200; ++i) doc["nodes"].push_back({{"children", {i + 1}}});
  doc["nodes"].push_back({{"mesh", 0}});
  EXPECT_EQ(load_gltf(write("chain.gltf", doc)).instances.size(), 1u);
}

// --- KHR_lights_punctual ---

TEST_F(GltfHostile, PunctualLightValuesAreChecked) {
  const double pi = std::numbers::pi;
  struct Case {
    std::string name;
    json light;
    std::string expected;
  };
  for (const Case& c : std::vector<Case>{
           {"negative-intensity",
            {{"type", "spot"}, {"intensity", -1}, {"spot", json::object()}},
            "lights[0].intensity: -1.000000 must be a finite number ≥ 0"},
           {"inner-outer",
            {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.5}}}},
            "lights[0].spot.innerConeAngle: 0.600000 must be ≥ 0 and less than outerConeAngle"},
           {"inner-equal",
            {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.5}}}},
            "lights[0].spot.innerConeAngle"},
           {"outer-wide",
            {{"type", "spot"}, {"spot", {{"outerConeAngle", pi / 2 + 0.01}}}},
            "lights[0].spot.outerConeAngle: 1.580796 must be in (0, π/2]"},
           {"range-zero",
            {{"type", "point"}, {"range", 0}},
            "lights[0].range: 0.000000 must be > 0"},
           {"range-negative", {{"type", "point"}, {"range", -3}}, "lights[0].range"},
           {"type", {{"type", "area"}}, "lights[0].type: unknown light type 'area'"},
           {"color", {{"type", "point"}, {"color", {1, -1, 1}}}, "lights[0].color"},
       }) {
    json doc = triangle();
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({c.light})}}}};
    doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    doc["scenes"][0]["nodes"].push_back(1);
    expect_error(doc, c.name + ".gltf",
                 {c.name + ".gltf", "extensions.KHR_lights_punctual." + c.expected});
  }
}

// --- Images: a warning and the missing-image checker for base colour, never an abort ---

TEST_F(GltfHostile, UnreadableImagesWarnOnceAndShowThePlaceholder) {
  std::vector<uint8_t> not_png = {0x89, 'P', 'N', 'G', 1, 2, 3};
  struct Case {
    std::string name;
    json image;
    std::string expected;
  };
  for (const Case& c : std::vector<Case>{
           {"absolute", {{"uri", "/nonexistent-obscura-dir/albedo.png"}}, "albedo.png"},
           {"corrupt",
            {{"uri", "data:image/png;base64," + base64(not_png)}},
            "corrupt.gltf: images[0]"},
           {"view-past-buffer",
            {{"bufferView", 3}, {"mimeType", "image/png"}},
            "runs past the end of its buffer"},
       }) {
    json doc = triangle();
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 600}, {"byteLength", 4000}});
    doc["images"] = json::array({c.image});  // not {c.image}: clang reads that as a copy
    doc["textures"] = {{{"source", 0}}};
    doc["materials"] = {
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    Scene scene = load_gltf(write(c.name + ".gltf", doc));
    EXPECT_EQ(count_warnings(scene, c.expected), 1) << c.name;
    const auto& mr = std::get<MetallicRoughnessMaterial>(scene.materials[0].model);
    ASSERT_TRUE(mr.base_color_texture.valid()) << c.name;
    EXPECT_EQ(scene.textures.at(size_t(mr.base_color_texture.texture)).name,
              "missing-image placeholder")
        << c.name;
    EXPECT_FLOAT_EQ(mr.base_color.g, 0.25f) << c.name;
  }
}

}  // namespace
}  // namespace obscura
