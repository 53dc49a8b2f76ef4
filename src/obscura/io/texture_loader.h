// Texture images decoded by the image codecs (image_codecs.h), from a file or from bytes in memory
// (glTF's embedded images).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "obscura/scene/texture.h"

namespace obscura {

// Reads an image file into a Texture (8-bit files stay 8-bit, others become float). Throws
// obscura::Error naming the file when it is missing or cannot be decoded.
Texture read_texture(const std::string& path, TextureEncoding encoding);

// Decodes an encoded image (PNG, JPEG, …) held in memory. `source` names it in messages, and
// `format_hint` is a file extension ("png", "jpg") or MIME type; may be empty.
Texture decode_texture(std::span<const uint8_t> bytes, const std::string& source,
                       const std::string& format_hint, TextureEncoding encoding);

}  // namespace obscura
