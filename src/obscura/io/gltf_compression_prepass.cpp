#include "obscura/io/gltf_compression_prepass.h"

#include <cstring>
#include <nlohmann/json.hpp>
#include <string_view>

namespace obscura {

namespace {

using nlohmann::json;

constexpr uint32_t kGlbJson = 0x4E4F534A;  // "JSON", the type of a GLB's first chunk

bool is_absent_fallback(const json& buffer) {
  if (!buffer.is_object() || buffer.contains("uri")) return false;
  auto ext = buffer.find("extensions");
  if (ext == buffer.end() || !ext->is_object()) return false;
  auto meshopt = ext->find("EXT_meshopt_compression");
  if (meshopt == ext->end() || !meshopt->is_object()) return false;
  auto fallback = meshopt->find("fallback");
  return fallback != meshopt->end() && fallback->is_boolean() && fallback->get<bool>();
}

bool stub_fallback_buffers(json& doc) {
  auto buffers = doc.find("buffers");
  if (buffers == doc.end() || !buffers->is_array()) return false;
  bool changed = false;
  for (json& buffer : *buffers)
    if (is_absent_fallback(buffer)) {
      buffer["uri"] = kAbsentFallbackUri;
      buffer["byteLength"] = 3;
      changed = true;
    }
  return changed;
}

bool give_draco_indices_a_view(json& doc) {
  auto meshes = doc.find("meshes");
  auto accessors = doc.find("accessors");
  if (meshes == doc.end() || !meshes->is_array() || accessors == doc.end() ||
      !accessors->is_array())
    return false;
  bool changed = false;
  for (json& mesh : *meshes) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
      continue;
    for (json& primitive : mesh["primitives"]) {
      if (!primitive.is_object()) continue;
      const json* draco = nullptr;
      auto ext = primitive.find("extensions");
      if (ext != primitive.end() && ext->is_object() && ext->contains("KHR_draco_mesh_compression"))
        draco = &(*ext)["KHR_draco_mesh_compression"];
      auto indices = primitive.find("indices");
      if (!draco || !draco->is_object() || !draco->contains("bufferView") ||
          !(*draco)["bufferView"].is_number_unsigned() || indices == primitive.end() ||
          !indices->is_number_unsigned() || indices->get<uint64_t>() >= accessors->size())
        continue;
      json& accessor = (*accessors)[indices->get<size_t>()];
      if (!accessor.is_object() || accessor.contains("bufferView")) continue;
      accessor["bufferView"] = (*draco)["bufferView"];
      changed = true;
    }
  }
  return changed;
}

// Both adjustments; false when neither applied.
bool adjust(json& doc) {
  if (!doc.is_object()) return false;
  bool stubbed = stub_fallback_buffers(doc);
  bool viewed = give_draco_indices_a_view(doc);
  return stubbed || viewed;
}

uint32_t read_u32(const uint8_t* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}
void append_u32(std::vector<uint8_t>& out, uint32_t v) {
  const auto* p = reinterpret_cast<const uint8_t*>(&v);
  out.insert(out.end(), p, p + 4);
}

}  // namespace

std::optional<std::vector<uint8_t>> prepare_compressed_gltf(std::span<const uint8_t> bytes) {
  std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  // The common case costs one search and no parse.
  if (text.find("EXT_meshopt_compression") == std::string_view::npos &&
      text.find("KHR_draco_mesh_compression") == std::string_view::npos)
    return std::nullopt;

  bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (!binary) {
    json doc = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !adjust(doc)) return std::nullopt;
    std::string out = doc.dump();
    return std::vector<uint8_t>(out.begin(), out.end());
  }
  // GLB: a 12-byte header, the JSON chunk, then an optional BIN chunk (glTF 2.0 §4.4).
  if (bytes.size() < 20) return std::nullopt;
  uint64_t json_size = read_u32(bytes.data() + 12);
  if (read_u32(bytes.data() + 16) != kGlbJson || 20 + json_size > bytes.size()) return std::nullopt;
  json doc = json::parse(text.substr(20, json_size), nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded() || !adjust(doc)) return std::nullopt;
  std::string json_text = doc.dump();
  json_text.resize((json_text.size() + 3) / 4 * 4, ' ');  // chunks stay 4-byte aligned
  std::span<const uint8_t> rest = bytes.subspan(20 + json_size);
  std::vector<uint8_t> out(bytes.begin(), bytes.begin() + 8);  // magic and version
  append_u32(out, 0);                                          // total length, set below
  append_u32(out, uint32_t(json_text.size()));
  append_u32(out, kGlbJson);
  out.insert(out.end(), json_text.begin(), json_text.end());
  out.insert(out.end(), rest.begin(), rest.end());
  if (out.size() > UINT32_MAX) return std::nullopt;
  uint32_t total = uint32_t(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

}  // namespace obscura
