// Texture images decoded by the image codecs (image_codecs.h), from a file or from bytes in memory
// (glTF's embedded images).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "obscura/scene/texture.h"

namespace obscura {

// The largest |value| a linear float texel may keep: an environment map's texels are radiance,
// bounded like a light's (kMaxLightValue, math/value_limits.h); data textures (normals,
// metallic-roughness) are far below it. An sRGB-encoded (colour) float texel is kept within
// [0, 1], the range the encoding covers: beyond it the decoding (a power of 2.4) and the
// bounces of a path multiply an albedo above 1 to infinity. No texture carries a NaN, an
// infinity or such a value into either renderer: the readers below replace a texel that is NaN
// by 0, and one beyond its range (±inf included) by the nearest bound.
inline constexpr double kMaxTexelValue = 1e12;

// Reads an image file into a Texture (8-bit files stay 8-bit, others become float). Throws
// obscura::Error naming the file when it is missing or cannot be decoded. Float texels are made
// usable as above; when any was replaced, one warning naming the file and how many values it
// replaced is appended to `warnings` (a loader passes its Scene::warnings). 8- and 16-bit files
// hold nothing to replace.
Texture read_texture(const std::string& path, TextureEncoding encoding,
                     std::vector<std::string>* warnings = nullptr);

// Decodes an encoded image (PNG, JPEG, …) held in memory. `source` names it in messages and
// warnings, and `format_hint` is a file extension ("png", "jpg") or MIME type; may be empty.
Texture decode_texture(std::span<const uint8_t> bytes, const std::string& source,
                       const std::string& format_hint, TextureEncoding encoding,
                       std::vector<std::string>* warnings = nullptr);

}  // namespace obscura
