#include "obscura/io/gltf_meshopt.h"

#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "obscura/io/gltf_decompressed_buffers.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";
// Three zero bytes: what a stubbed fallback buffer holds (a view that reads it fails its range
// check, or is named by decode_meshopt_buffer_views).
constexpr const char* kStubUri = "data:application/octet-stream;base64,AAAA";
constexpr uint32_t kGlbJson = 0x4E4F534A;  // "JSON", the first chunk's type

bool is_absent_fallback(const nlohmann::json& buffer) {
  if (!buffer.is_object() || buffer.contains("uri")) return false;
  auto ext = buffer.find("extensions");
  if (ext == buffer.end() || !ext->is_object()) return false;
  auto meshopt = ext->find(kExtension);
  if (meshopt == ext->end() || !meshopt->is_object()) return false;
  auto fallback = meshopt->find("fallback");
  return fallback != meshopt->end() && fallback->is_boolean() && fallback->get<bool>();
}

// Gives each absent fallback buffer of `doc` the stub; false when there is none.
bool stub_buffers(nlohmann::json& doc) {
  if (!doc.is_object()) return false;
  auto buffers = doc.find("buffers");
  if (buffers == doc.end() || !buffers->is_array()) return false;
  bool changed = false;
  for (nlohmann::json& buffer : *buffers)
    if (is_absent_fallback(buffer)) {
      buffer["uri"] = kStubUri;
      buffer["byteLength"] = 3;
      changed = true;
    }
  return changed;
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

// The parts of the extension object on one bufferView, range-checked.
struct Compressed {
  const uint8_t* data = nullptr;
  uint64_t size = 0;
  uint64_t count = 0, stride = 0;
  std::string mode, filter;
};

class ViewReader {
 public:
  ViewReader(const tinygltf::Value& ext, std::string at) : ext_(ext), at_(std::move(at)) {}

  uint64_t unsigned_integer(const char* key, std::optional<uint64_t> fallback) const {
    if (!ext_.Has(key)) {
      if (!fallback) fail(key, "is required");
      return *fallback;
    }
    const tinygltf::Value& v = ext_.Get(key);
    double d = v.IsNumber() ? v.GetNumberAsDouble() : -1;
    if (!(d >= 0 && d <= 9007199254740992.0 && d == std::floor(d)))
      fail(key, "expected a non-negative integer");
    return uint64_t(d);
  }
  std::string text(const char* key, std::optional<std::string> fallback) const {
    if (!ext_.Has(key)) {
      if (!fallback) fail(key, "is required");
      return *fallback;
    }
    const tinygltf::Value& v = ext_.Get(key);
    if (!v.IsString()) fail(key, "expected a string");
    return v.Get<std::string>();
  }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw Error(at_ + "." + key, message);
  }
  const std::string& at() const { return at_; }

 private:
  const tinygltf::Value& ext_;
  std::string at_;
};

Compressed read_extension(const tinygltf::Model& model, const ViewReader& r) {
  Compressed c;
  uint64_t buffer = r.unsigned_integer("buffer", std::nullopt);
  uint64_t offset = r.unsigned_integer("byteOffset", 0);
  c.size = r.unsigned_integer("byteLength", std::nullopt);
  c.stride = r.unsigned_integer("byteStride", std::nullopt);
  c.count = r.unsigned_integer("count", std::nullopt);
  c.mode = r.text("mode", std::nullopt);
  c.filter = r.text("filter", "NONE");
  if (buffer >= model.buffers.size())
    r.fail("buffer", "buffer " + std::to_string(buffer) + " is out of range (the file has " +
                         std::to_string(model.buffers.size()) + ")");
  const std::vector<unsigned char>& data = model.buffers[buffer].data;
  uint64_t end = 0;
  if (__builtin_add_overflow(offset, c.size, &end) || end > data.size())
    r.fail("byteLength", "byteOffset " + std::to_string(offset) + " + byteLength " +
                             std::to_string(c.size) + " exceeds buffer " + std::to_string(buffer) +
                             " (" + std::to_string(data.size()) + " bytes)");
  c.data = data.data() + offset;
  if (c.count == 0) r.fail("count", "must be at least 1");

  if (c.mode == "ATTRIBUTES") {
    if (c.stride == 0 || c.stride > 256 || c.stride % 4 != 0)
      r.fail("byteStride", std::to_string(c.stride) +
                               " must be a multiple of 4 from 4 to 256 in mode ATTRIBUTES");
  } else if (c.mode == "TRIANGLES" || c.mode == "INDICES") {
    if (c.stride != 2 && c.stride != 4)
      r.fail("byteStride", std::to_string(c.stride) + " must be 2 or 4 in mode " + c.mode);
    if (c.mode == "TRIANGLES" && c.count % 3 != 0)
      r.fail("count", std::to_string(c.count) + " must be a multiple of 3 in mode TRIANGLES");
    // Every triangle takes at least one byte of code, every index of a sequence at least one
    // byte: a larger count cannot decode, so refuse it before allocating for it.
    uint64_t least = c.mode == "TRIANGLES" ? c.count / 3 + 17 : c.count + 5;
    if (c.size < least)
      r.fail("count", std::to_string(c.count) + " indices cannot come from " +
                          std::to_string(c.size) + " compressed bytes");
  } else {
    r.fail("mode", "'" + c.mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
  }
  if (c.filter != "NONE") {
    if (c.mode != "ATTRIBUTES")
      r.fail("filter", "filter " + c.filter + " is only allowed in mode ATTRIBUTES");
    if (c.filter == "OCTAHEDRAL") {
      if (c.stride != 4 && c.stride != 8)
        r.fail("byteStride", std::to_string(c.stride) + " must be 4 or 8 for filter OCTAHEDRAL");
    } else if (c.filter == "QUATERNION") {
      if (c.stride != 8)
        r.fail("byteStride", std::to_string(c.stride) + " must be 8 for filter QUATERNION");
    } else if (c.filter != "EXPONENTIAL") {  // any multiple of 4, checked above
      r.fail("filter", "'" + c.filter + "' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
    }
  }
  return c;
}

std::vector<unsigned char> decode(const Compressed& c, const std::string& at,
                                  GltfDecompressedBuffers& buffers) {
  uint64_t bytes = 0;
  if (__builtin_mul_overflow(c.count, c.stride, &bytes))
    throw Error(at, "count × byteStride overflows");
  buffers.charge(bytes, at);
  std::vector<unsigned char> out(bytes);
  int status = 0;
  if (c.mode == "ATTRIBUTES")
    status = meshopt_decodeVertexBuffer(out.data(), c.count, c.stride, c.data, c.size);
  else if (c.mode == "TRIANGLES")
    status = meshopt_decodeIndexBuffer(out.data(), c.count, c.stride, c.data, c.size);
  else
    status = meshopt_decodeIndexSequence(out.data(), c.count, c.stride, c.data, c.size);
  if (status != 0)
    throw Error(at, "the compressed data does not decode to " + std::to_string(c.count) + " " +
                        (c.mode == "ATTRIBUTES" ? "elements" : "indices") + " of " +
                        std::to_string(c.stride) + " bytes (mode " + c.mode + ", meshoptimizer " +
                        "error " + std::to_string(status) + "): truncated or corrupt");
  if (c.filter == "OCTAHEDRAL")
    meshopt_decodeFilterOct(out.data(), c.count, c.stride);
  else if (c.filter == "QUATERNION")
    meshopt_decodeFilterQuat(out.data(), c.count, c.stride);
  else if (c.filter == "EXPONENTIAL")
    meshopt_decodeFilterExp(out.data(), c.count, c.stride);
  return out;
}

bool is_stub(const tinygltf::Buffer& buffer) {
  return buffer.uri == kStubUri && buffer.extensions.count(kExtension);
}

}  // namespace

std::optional<std::vector<uint8_t>> stub_absent_meshopt_fallbacks(std::span<const uint8_t> bytes) {
  static constexpr std::string_view kName = "EXT_meshopt_compression";
  std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (text.find(kName) == std::string_view::npos) return std::nullopt;  // the common case

  bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (!binary) {
    nlohmann::json doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !stub_buffers(doc)) return std::nullopt;
    std::string out = doc.dump();
    return std::vector<uint8_t>(out.begin(), out.end());
  }
  // GLB: a 12-byte header, the JSON chunk, then an optional BIN chunk (glTF 2.0 §4.4).
  if (bytes.size() < 20) return std::nullopt;
  uint64_t json_size = read_u32(bytes.data() + 12);
  if (read_u32(bytes.data() + 16) != kGlbJson || 20 + json_size > bytes.size()) return std::nullopt;
  nlohmann::json doc = nlohmann::json::parse(text.substr(20, json_size), nullptr, false);
  if (doc.is_discarded() || !stub_buffers(doc)) return std::nullopt;
  std::string json_text = doc.dump();
  json_text.resize((json_text.size() + 3) / 4 * 4, ' ');
  std::span<const uint8_t> rest = bytes.subspan(20 + json_size);
  std::vector<uint8_t> out(bytes.begin(), bytes.begin() + 8);
  append_u32(out, 0);  // total length, filled below
  append_u32(out, uint32_t(json_text.size()));
  append_u32(out, kGlbJson);
  out.insert(out.end(), json_text.begin(), json_text.end());
  out.insert(out.end(), rest.begin(), rest.end());
  if (out.size() > UINT32_MAX) return std::nullopt;
  uint32_t total = uint32_t(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

void decode_meshopt_buffer_views(tinygltf::Model& model, const std::string& file,
                                 GltfDecompressedBuffers& buffers) {
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    tinygltf::BufferView& view = model.bufferViews[i];
    const std::string at = file + ": bufferViews[" + std::to_string(i) + "]";
    auto found = view.extensions.find(kExtension);
    if (found == view.extensions.end()) {
      if (view.buffer >= 0 && size_t(view.buffer) < model.buffers.size() &&
          is_stub(model.buffers[size_t(view.buffer)]))
        throw Error(at, "reads buffer " + std::to_string(view.buffer) +
                            ", an EXT_meshopt_compression fallback buffer whose data the file "
                            "leaves out, without being compressed itself");
      continue;
    }
    if (!found->second.IsObject()) throw Error(at + ".extensions." + kExtension, "not an object");
    ViewReader reader(found->second, at + ".extensions." + kExtension);
    Compressed c = read_extension(model, reader);
    if (view.byteStride != 0 && view.byteStride != c.stride)
      reader.fail("byteStride", std::to_string(c.stride) + " differs from the bufferView's " +
                                    std::to_string(view.byteStride));
    if (uint64_t(view.byteLength) > c.count * c.stride)
      throw Error(at, "byteLength " + std::to_string(view.byteLength) +
                          " is more than the decompressed count × byteStride = " +
                          std::to_string(c.count * c.stride));
    std::vector<unsigned char> decoded = decode(c, reader.at(), buffers);
    view.buffer = buffers.append(std::move(decoded));
    view.byteOffset = 0;
  }
}

}  // namespace obscura
