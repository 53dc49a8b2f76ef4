#include "obscura/io/gltf_meshopt.h"

#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

#include "obscura/io/gltf_compression_prepass.h"
#include "obscura/io/gltf_decompressed_buffers.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

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
  return buffer.uri == kAbsentFallbackUri && buffer.extensions.count(kExtension);
}

}  // namespace

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
