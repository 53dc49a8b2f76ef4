// KHR_draco_mesh_compression: a primitive's indices and vertex attributes stored as one Draco
// mesh in a bufferView; the primitive's accessors say how many elements of which type it holds.
#pragma once

#include <string>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

class GltfDecompressedBuffers;

// Decodes every primitive's Draco mesh into new buffers, in the component type, element type
// and normalization its accessors declare, and points those accessors at them (the rest of the
// loader then reads them like uncompressed data). Throws obscura::Error naming `file` and the
// primitive for anything malformed: a stream Draco cannot decode, an attribute id it does not
// have, element counts or component counts that differ from the accessors', indices out of
// range.
void decode_draco_primitives(tinygltf::Model& model, const std::string& file,
                             GltfDecompressedBuffers& buffers);

}  // namespace obscura
