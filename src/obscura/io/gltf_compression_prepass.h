// The JSON of a glTF file with compressed geometry, adjusted before tinygltf parses it, because
// tinygltf (Debian 12's 2.8) refuses two things such files legitimately contain:
//  - EXT_meshopt_compression: a fallback buffer without a uri (its data left out of the file);
//    tinygltf wants a uri in a .gltf and hands a GLB's BIN chunk to every uri-less buffer. It
//    gets a 3-byte data URI instead; decode_meshopt_buffer_views redirects the views that use
//    it and names any view that would still read it.
//  - KHR_draco_mesh_compression: an indices accessor without a bufferView (its data is in the
//    Draco stream); tinygltf wants one. It gets the primitive's Draco bufferView, which
//    decode_draco_primitives replaces with the decoded indices.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace obscura {

// The uri an absent meshopt fallback buffer is given.
inline constexpr const char* kAbsentFallbackUri = "data:application/octet-stream;base64,AAAA";

// The file (JSON, or GLB with its JSON chunk rewritten) with both adjustments, or nothing when
// it needs neither (or is not well-formed enough to tell: tinygltf then says why).
std::optional<std::vector<uint8_t>> prepare_compressed_gltf(std::span<const uint8_t> bytes);

}  // namespace obscura
