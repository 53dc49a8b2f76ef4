// A fixture for hostile-glTF tests: a one-triangle file built as JSON in the test, which each
// test breaks in one place, and expect_error() that checks the message and that it came fast.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "obscura/io/gltf_loader.h"
#include "obscura/math/error.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura::test {

using nlohmann::json;

constexpr uint64_t kCount2To62 = uint64_t(1) << 62;  // 4611686018427387904

// A glTF document built as JSON in the test, loaded from memory (relative URIs against ".").
inline Scene load_gltf_json(const json& document, const GltfLoadOptions& options = {},
                            const std::string& name = "test.gltf") {
  std::string text = document.dump();
  return load_gltf_bytes({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, name, ".",
                         options);
}

// `load(document)` throws obscura::Error whose message names `field` (e.g.
// "materials[0].extensions.KHR_materials_sheen.sheenColorFactor").
template <class Load>
void expect_error_naming(Load load, const json& document, const std::string& field) {
  try {
    load(document);
    ADD_FAILURE() << "no error for " << field;
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(field));
  }
}

inline std::string base64(const std::vector<uint8_t>& bytes) {
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
 public:
  std::string dir = make_temp_dir("obscura-gltf-hostile");
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
  // Replaces buffer 0 with `bytes` (embedded as a data URI).
  static void set_buffer(json& doc, const std::vector<uint8_t>& bytes) {
    doc["buffers"][0] = {{"byteLength", bytes.size()},
                         {"uri", "data:application/octet-stream;base64," + base64(bytes)}};
  }
  static int count_warnings(const Scene& scene, const std::string& fragment) {
    int n = 0;
    for (const std::string& w : scene.warnings) n += w.find(fragment) != std::string::npos;
    return n;
  }
  static bool has_warning(const Scene& scene, const std::string& fragment) {
    for (const std::string& w : scene.warnings)
      if (w.find(fragment) != std::string::npos) return true;
    return false;
  }
};

}  // namespace obscura::test
