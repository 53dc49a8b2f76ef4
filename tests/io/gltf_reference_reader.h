// A minimal glTF reader for tests, independent of the loader under test and of tinygltf: the
// JSON through nlohmann, buffers from .bin files or the GLB BIN chunk, accessors decoded here by
// the specification's layout rules (FLOAT, UNSIGNED_BYTE / UNSIGNED_SHORT, byteStride; no
// sparse). Only for the trusted sample files in tests/data/.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace obscura::test {

class ReferenceGltf {
 public:
  explicit ReferenceGltf(const std::string& path) {
    std::vector<char> bytes = read(path);
    if (bytes.size() >= 20 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
      uint32_t json_length = 0, bin_length = 0;
      std::memcpy(&json_length, bytes.data() + 12, 4);
      json = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
      size_t bin = 20 + json_length;
      std::memcpy(&bin_length, bytes.data() + bin, 4);
      buffers.emplace_back(bytes.begin() + long(bin) + 8,
                           bytes.begin() + long(bin) + 8 + bin_length);
    } else {
      json = nlohmann::json::parse(bytes.begin(), bytes.end());
      std::filesystem::path dir = std::filesystem::path(path).parent_path();
      for (const auto& b : json["buffers"])
        buffers.push_back(read((dir / b["uri"].get<std::string>()).string()));
    }
  }

  // Accessor `index` as floats, `components` per element (normalized integers mapped to [0, 1]).
  std::vector<float> floats(int index) const {
    const nlohmann::json& a = json["accessors"][index];
    const nlohmann::json& view = json["bufferViews"][a["bufferView"].get<int>()];
    const int type = a["componentType"];
    const size_t size = type == 5126 ? 4 : type == 5123 ? 2 : 1;
    const size_t n = components(index), count = a["count"];
    const size_t stride =
        view.value("byteStride", size_t(0)) ? size_t(view["byteStride"]) : n * size;
    const bool normalized = a.value("normalized", false);
    const char* base = buffers[view["buffer"].get<size_t>()].data() +
                       view.value("byteOffset", size_t(0)) + a.value("byteOffset", size_t(0));
    std::vector<float> out;
    for (size_t i = 0; i < count; ++i)
      for (size_t c = 0; c < n; ++c) {
        const char* p = base + i * stride + c * size;
        float v = 0;
        if (type == 5126) {
          std::memcpy(&v, p, 4);
        } else if (type == 5123) {
          uint16_t u;
          std::memcpy(&u, p, 2);
          v = normalized ? float(u) / 65535.f : float(u);
        } else {
          uint8_t u;
          std::memcpy(&u, p, 1);
          v = normalized ? float(u) / 255.f : float(u);
        }
        out.push_back(v);
      }
    return out;
  }

  size_t components(int index) const {
    std::string type = json["accessors"][index]["type"];
    if (type == "SCALAR") return 1;
    if (type == "MAT4") return 16;
    return size_t(type.back() - '0');  // VEC2, VEC3, VEC4
  }

  nlohmann::json json;
  std::vector<std::vector<char>> buffers;

 private:
  static std::vector<char> read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in) << "cannot read " << path;
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

}  // namespace obscura::test
