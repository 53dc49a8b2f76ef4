// Hostile and invalid glTF files (issue 12): each is built here as JSON (or GLB bytes) and must
// give an obscura::Error naming the file and the JSON path, never a crash, a huge allocation or
// a silently accepted file. The rules come from the glTF 2.0 specification (§3.6 accessors and
// buffer views, §3.5 nodes, §3.11 animations, §5 asset, KHR_lights_punctual).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "obscura/io/gltf_loader.h"
#include "obscura/math/error.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

using nlohmann::json;

constexpr uint64_t kCount2To62 = uint64_t(1) << 62;  // 4611686018427387904

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = bytes[i] << 16 | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                 (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += digits[v >> 18 & 63];
    out += digits[v >> 12 & 63];
    out += i + 1 < bytes.size() ? digits[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

class GltfHostile : public testing::Test {
 protected:
  std::string dir = test::make_temp_dir("obscura-gltf-hostile");
  ~GltfHostile() override {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }

  // One triangle in a 648-byte buffer: positions at 0 (36 bytes), uint16 indices at 36 (6
  // bytes), zeros after. bufferViews: 0 positions, 1 indices, 2 the whole buffer.
  // accessors: 0 POSITION, 1 indices.
  static std::vector<uint8_t> buffer_bytes() {
    std::vector<uint8_t> bytes(648, 0);
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t indices[3] = {0, 1, 2};
    std::memcpy(bytes.data(), positions, sizeof positions);
    std::memcpy(bytes.data() + 36, indices, sizeof indices);
    return bytes;
  }
  static json triangle() {
    return {
        {"asset", {{"version", "2.0"}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
        {"buffers",
         {{{"byteLength", 648},
           {"uri", "data:application/octet-stream;base64," + base64(buffer_bytes())}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
          {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}},
          {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 648}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
    };
  }
  // Adds an accessor, returns its index.
  static int add_accessor(json& doc, json accessor) {
    doc["accessors"].push_back(std::move(accessor));
    return int(doc["accessors"].size()) - 1;
  }
  std::string write(const std::string& name, const std::string& bytes) {
    std::string path = dir + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  std::string write(const std::string& name, const json& doc) { return write(name, doc.dump()); }

  // Loads and expects an obscura::Error containing every fragment; the error must come fast
  // (no huge allocation or loop before it).
  void expect_error(const std::string& path, const std::vector<std::string>& fragments) {
    auto start = std::chrono::steady_clock::now();
    try {
      load_gltf(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const Error& e) {
      for (const std::string& f : fragments) EXPECT_THAT(e.what(), testing::HasSubstr(f));
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0)
        << path;
  }
  void expect_error(const json& doc, const std::string& name,
                    const std::vector<std::string>& fragments) {
    expect_error(write(name, doc), fragments);
  }
  static bool has_warning(const Scene& scene, const std::string& fragment) {
    for (const std::string& w : scene.warnings)
      if (w.find(fragment) != std::string::npos) return true;
    return false;
  }
};

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

}  // namespace
}  // namespace obscura
