// Decoding through OpenImageIO, behind ImageDecoder (obscura/io/image_codecs.h).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "obscura/io/image_codecs.h"

namespace obscura::oiio {

// Opens an image with the named OpenImageIO reader only; see ImageCodecs::open.
std::unique_ptr<ImageDecoder> open_image(const std::string& reader, const std::string& name,
                                         bool from_memory, std::span<const uint8_t> memory,
                                         const std::string& source);

}  // namespace obscura::oiio
