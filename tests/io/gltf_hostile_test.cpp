// Hostile and invalid glTF files (issue 12): each is built here as JSON (or GLB bytes) and must
// give an obscura::Error naming the file and the JSON path, never a crash, a huge allocation or
// a silently accepted file. The rules come from the glTF 2.0 specification (§3.6 accessors and
// buffer views, §3.5 nodes, §3.11 animations, §5 asset, KHR_lights_punctual).
#include "io/gltf_hostile.h"

#include "run_command.h"

namespace obscura {
namespace {

using nlohmann::json;
using test::base64;
using test::GltfHostile;
using test::kCount2To62;

// --- Accessors (issue 12 items 1, 2, 6) ---

TEST_F(GltfHostile, TheBaseTriangleLoads) {
  Scene scene = load_gltf(write("ok.gltf", triangle()));
  EXPECT_EQ(scene.stats().triangles, 1u);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST_F(GltfHostile, CountNear2To62OverflowsNoMoreForAnyAttribute) {
  // The 546-byte crash: count × stride wrapped in size_t. Each attribute as the only one of
  // its kind with a count of 2^62 over the 648-byte view; POSITION too, so that the per-element
  // count check before reading cannot hide the reader's own check.
  for (auto [key, type] : {std::pair{"COLOR_0", "VEC4"}, std::pair{"TANGENT", "VEC4"},
                           std::pair{"TEXCOORD_0", "VEC2"}, std::pair{"POSITION", "VEC3"}}) {
    json doc = triangle();
    int a = add_accessor(
        doc, {{"bufferView", 2}, {"componentType", 5126}, {"count", kCount2To62}, {"type", type}});
    doc["meshes"][0]["primitives"][0]["attributes"][key] = a;
    if (std::string(key) == "POSITION") doc["meshes"][0]["primitives"][0].erase("indices");
    std::string name = std::string("count-") + key + ".gltf";
    int stride = std::string(type) == "VEC4" ? 16 : std::string(type) == "VEC3" ? 12 : 8;
    expect_error(doc, name,
                 {name, std::string("meshes[0].primitives[0].attributes.") + key + " (accessor 2)",
                  "count 4611686018427387904 × stride " + std::to_string(stride) +
                      " exceeds bufferView 2 (648 bytes)"});
  }
}

TEST_F(GltfHostile, ZeroFilledAccessorWithAHugeCountIsBounded) {
  // No bufferView: all zeros, as the spec says, but 2^62 of them is refused before allocating.
  json doc = triangle();
  doc["accessors"][0] = {{"componentType", 5126}, {"count", kCount2To62}, {"type", "VEC3"}};
  doc["meshes"][0]["primitives"][0].erase("indices");
  expect_error(doc, "zeros.gltf", {"zeros.gltf", "attributes.POSITION (accessor 0)", "too large"});
  // 2^27 VEC3 zeros = 1.5 GiB of floats: over the decode budget.
  doc["accessors"][0]["count"] = uint64_t(1) << 27;
  expect_error(doc, "zeros-budget.gltf", {"zeros-budget.gltf", "decode to more than 1024 MiB"});
}

TEST_F(GltfHostile, IndicesWithCount2To31Minus1FailBeforeAllocating) {
  json doc = triangle();
  doc["accessors"][1]["bufferView"] = 2;
  doc["accessors"][1]["componentType"] = 5125;
  doc["accessors"][1]["count"] = 2147483647;
  expect_error(doc, "indices.gltf",
               {"indices.gltf", "meshes[0].primitives[0].indices (accessor 1)",
                "count 2147483647 × stride 4 exceeds bufferView 2 (648 bytes)"});
}

TEST_F(GltfHostile, AccessorLayoutRulesOfTheSpec) {
  struct Case {
    std::string name;
    json accessor_change, view_change;
    std::string expected;
  };
  std::vector<Case> cases = {
      {"stride-small", {}, {{"byteStride", 8}}, "byteStride 8 must be a multiple of 4 from 12"},
      {"stride-big", {}, {{"byteStride", 256}}, "byteStride"},
      {"offset-misaligned", {{"byteOffset", 2}}, {}, "not a multiple of the component size 4"},
      {"normalized-float", {{"normalized", true}}, {}, "normalized must not be true for FLOAT"},
      {"count-zero", {{"count", 0}}, {}, "count must be at least 1"},
      {"past-view", {{"byteOffset", 4}}, {}, "count 3 × stride 12 from byteOffset 4 exceeds"},
      {"view-past-buffer", {}, {{"byteOffset", 640}}, "exceeds buffer 0 (648 bytes)"},
      {"view-overflow", {}, {{"byteOffset", uint64_t(18446744073709551600u)}}, "bufferViews[0]"},
      {"bad-view", {{"bufferView", 9}}, {}, "bufferView 9 is out of range"},
      {"matrix", {{"type", "MAT3"}}, {}, "expected VEC3, got MAT3"},
      {"uint-positions", {{"componentType", 5125}}, {}, "UNSIGNED_INT is not allowed here"},
  };
  for (const Case& c : cases) {
    json doc = triangle();
    for (auto& [k, v] : c.accessor_change.items()) doc["accessors"][0][k] = v;
    for (auto& [k, v] : c.view_change.items()) doc["bufferViews"][0][k] = v;
    std::string name = c.name + ".gltf";
    expect_error(doc, name, {name, c.expected});
  }
}

TEST_F(GltfHostile, IndicesMustBeUnsignedScalarsBelowTheVertexCount) {
  for (auto [name, change, expected] :
       {std::tuple{"float-indices", json{{"componentType", 5126}}, "indices must be UNSIGNED"},
        std::tuple{"vec-indices", json{{"type", "VEC3"}, {"count", 1}}, "must be SCALAR"},
        std::tuple{"normalized-indices", json{{"normalized", true}}, "normalized"}}) {
    json doc = triangle();
    for (auto& [k, v] : change.items()) doc["accessors"][1][k] = v;
    expect_error(doc, std::string(name) + ".gltf", {name, "indices (accessor 1)", expected});
  }
}

TEST_F(GltfHostile, QuantizedAndNormalizedAttributesDecodeAsTheSpecSays) {
  // KHR_mesh_quantization: SHORT positions kept as integers, normalized UNSIGNED_BYTE colours
  // c / 255, normalized BYTE normals max(c / 127, −1) (glTF 2.0 §3.11 animations / §3.7.2.1).
  std::vector<uint8_t> bytes(64, 0);
  const int16_t positions[12] = {0, 0, 0, 0, 300, 0, 0, 0, 0, -2, 0, 0};  // VEC3, stride 8
  std::memcpy(bytes.data(), positions, sizeof positions);
  const uint8_t colors[12] = {255, 0, 51, 0, 0, 255, 0, 0, 102, 0, 0, 0};  // VEC3, stride 4
  std::memcpy(bytes.data() + 24, colors, sizeof colors);
  const int8_t normals[12] = {-128, 0, 0, 0, 0, 127, 0, 0, 0, 0, -127, 0};  // VEC3, stride 4
  std::memcpy(bytes.data() + 36, normals, sizeof normals);
  json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_mesh_quantization"}},
      {"extensionsRequired", {"KHR_mesh_quantization"}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"COLOR_0", 1}, {"NORMAL", 2}}}}}}}}},
      {"buffers",
       {{{"byteLength", 64}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 24}, {"byteStride", 8}},
        {{"buffer", 0}, {"byteOffset", 24}, {"byteLength", 12}, {"byteStride", 4}},
        {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 12}, {"byteStride", 4}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5122}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 1},
         {"componentType", 5121},
         {"normalized", true},
         {"count", 3},
         {"type", "VEC3"}},
        {{"bufferView", 2},
         {"componentType", 5120},
         {"normalized", true},
         {"count", 3},
         {"type", "VEC3"}}}},
  };
  Scene scene = load_gltf(write("quantized.gltf", doc));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& m = scene.meshes[0];
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[1].x, 300.f);
  EXPECT_EQ(m.positions[2].y, -2.f);
  ASSERT_EQ(m.colors.size(), 3u);
  EXPECT_FLOAT_EQ(m.colors[0].r, 1.f);
  EXPECT_FLOAT_EQ(m.colors[0].b, 0.2f);  // 51 / 255
  EXPECT_FLOAT_EQ(m.colors[1].g, 1.f);
  EXPECT_FLOAT_EQ(m.colors[2].r, 0.4f);  // 102 / 255
  ASSERT_EQ(m.normals.size(), 3u);
  EXPECT_FLOAT_EQ(m.normals[0].x, -1.f);  // −128 / 127 clamps to −1
  EXPECT_FLOAT_EQ(m.normals[1].y, 1.f);   // 127 / 127
  EXPECT_FLOAT_EQ(m.normals[2].z, -1.f);  // −127 / 127
}

TEST_F(GltfHostile, QuantizedTexcoordsAndTangentsDecodeAsTheSpecSays) {
  // KHR_mesh_quantization also covers TEXCOORD_n (normalized or plain (UNSIGNED_)BYTE/SHORT)
  // and TANGENT (normalized BYTE/SHORT): normalized UNSIGNED_SHORT u / 65535, plain
  // UNSIGNED_BYTE kept as integers, normalized SHORT max(c / 32767, −1).
  json doc = triangle();
  std::vector<uint8_t> bytes = buffer_bytes();
  const uint16_t uvs[6] = {0, 65535, 32768, 0, 13107, 65535};  // VEC2, stride 4
  std::memcpy(bytes.data() + 44, uvs, sizeof uvs);
  const uint8_t uv_bytes[12] = {0, 1, 0, 0, 2, 3, 0, 0, 255, 0, 0, 0};  // VEC2, stride 4
  std::memcpy(bytes.data() + 56, uv_bytes, sizeof uv_bytes);
  const int16_t tangents[12] = {32767, 0, 0, 32767, 0, -32768, 0, -32767, 0, 0, 16384, 32767};
  std::memcpy(bytes.data() + 68, tangents, sizeof tangents);
  set_buffer(doc, bytes);
  doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 12}});
  doc["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", 56}, {"byteLength", 12}, {"byteStride", 4}});
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 68}, {"byteLength", 24}});
  int uv = add_accessor(doc, {{"bufferView", 3},
                              {"componentType", 5123},
                              {"normalized", true},
                              {"count", 3},
                              {"type", "VEC2"}});
  int tangent = add_accessor(doc, {{"bufferView", 5},
                                   {"componentType", 5122},
                                   {"normalized", true},
                                   {"count", 3},
                                   {"type", "VEC4"}});
  auto& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
  attributes["TEXCOORD_0"] = uv;
  attributes["TANGENT"] = tangent;
  Scene scene = load_gltf(write("quantized-uv.gltf", doc));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& m = scene.meshes[0];
  ASSERT_EQ(m.uvs.size(), 3u);
  EXPECT_FLOAT_EQ(m.uvs[0].y, 1.f);
  EXPECT_FLOAT_EQ(m.uvs[1].x, 32768.f / 65535);
  EXPECT_FLOAT_EQ(m.uvs[2].x, 0.2f);  // 13107 / 65535
  ASSERT_EQ(m.tangents.size(), 3u);
  EXPECT_FLOAT_EQ(m.tangents[0].x, 1.f);
  EXPECT_FLOAT_EQ(m.tangents[0].w, 1.f);
  EXPECT_FLOAT_EQ(m.tangents[1].y, -1.f);  // −32768 clamps to −1
  EXPECT_FLOAT_EQ(m.tangents[1].w, -1.f);
  EXPECT_FLOAT_EQ(m.tangents[2].z, 16384.f / 32767);

  // Plain (not normalized) UNSIGNED_BYTE texture coordinates keep their integer values.
  attributes["TEXCOORD_0"] = add_accessor(
      doc, {{"bufferView", 4}, {"componentType", 5121}, {"count", 3}, {"type", "VEC2"}});
  Scene plain = load_gltf(write("plain-uv.gltf", doc));
  ASSERT_EQ(plain.meshes.at(0).uvs.size(), 3u);
  EXPECT_EQ(plain.meshes[0].uvs[1].x, 2.f);
  EXPECT_EQ(plain.meshes[0].uvs[1].y, 3.f);
  EXPECT_EQ(plain.meshes[0].uvs[2].x, 255.f);
}

TEST_F(GltfHostile, AnUnsupportedOptionalExtensionIsOneWarningNamingIt) {
  json doc = triangle();
  doc["extensionsUsed"] = {"EXT_obscura_unknown_test"};
  doc["materials"] = {{{"extensions", {{"EXT_obscura_unknown_test", json::object()}}}}};
  doc["meshes"][0]["primitives"][0]["material"] = 0;
  Scene scene = load_gltf(write("optional.gltf", doc));
  EXPECT_EQ(count_warnings(scene, "EXT_obscura_unknown_test"), 1);
  EXPECT_TRUE(has_warning(scene, "optional.gltf: extension EXT_obscura_unknown_test"));
}

}  // namespace
}  // namespace obscura
