// EXT_meshopt_compression: bufferViews whose bytes are stored compressed by meshoptimizer, in
// another buffer, with an uncompressed "fallback" buffer that may be absent from the file (see
// gltf_compression_prepass.h for how such a file gets past tinygltf).
#pragma once

#include <string>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

class GltfDecompressedBuffers;

// Decodes every bufferView that carries EXT_meshopt_compression (modes ATTRIBUTES, TRIANGLES,
// INDICES; filters NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL) into a new buffer and points the
// view at it. Throws obscura::Error naming `file` and the bufferView for anything malformed:
// out-of-range fields, compressed data that does not decode to `count` elements, a view that
// still reads a stubbed fallback buffer.
void decode_meshopt_buffer_views(tinygltf::Model& model, const std::string& file,
                                 GltfDecompressedBuffers& buffers);

}  // namespace obscura
