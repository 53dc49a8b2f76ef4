// EXT_meshopt_compression: bufferViews whose bytes are stored compressed by meshoptimizer, in
// another buffer, with an uncompressed "fallback" buffer that may be absent from the file.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

class GltfDecompressedBuffers;

// tinygltf refuses a buffer without a uri in a .gltf (and hands a GLB's BIN chunk to every such
// buffer), yet an EXT_meshopt_compression fallback buffer has no uri when its data was left out.
// Returns the file (JSON or GLB) with each such buffer given a tiny data URI instead, or nothing
// when the file has none (or is not well-formed enough to tell: tinygltf then says why).
std::optional<std::vector<uint8_t>> stub_absent_meshopt_fallbacks(std::span<const uint8_t> bytes);

// Decodes every bufferView that carries EXT_meshopt_compression (modes ATTRIBUTES, TRIANGLES,
// INDICES; filters NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL) into a new buffer and points the
// view at it. Throws obscura::Error naming `file` and the bufferView for anything malformed:
// out-of-range fields, compressed data that does not decode to `count` elements, a view that
// still reads a stubbed fallback buffer.
void decode_meshopt_buffer_views(tinygltf::Model& model, const std::string& file,
                                 GltfDecompressedBuffers& buffers);

}  // namespace obscura
