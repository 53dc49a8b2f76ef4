#include "obscura/io/texture_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "obscura/io/image_reader.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"
#include "obscura/math/value_limits.h"

namespace obscura {

namespace {

static_assert(kMaxTexelValue <= kMaxLightValue, "an environment map's texel is a light's radiance");

// NaN → 0; below `low` (−inf included) → low; above `high` (+inf included) → high. Returns how
// many changed.
size_t replace_unusable_texels(std::vector<float>& texels, float low, float high) {
  size_t replaced = 0;
  for (float& v : texels) {
    if (std::isnan(v)) {
      v = 0;
    } else if (v < low) {
      v = low;
    } else if (v > high) {
      v = high;
    } else {
      continue;
    }
    ++replaced;
  }
  return replaced;
}

// Reads every pixel of an opened, checked image into a Texture.
Texture read_pixels(CheckedImageInput& in, TextureEncoding encoding,
                    std::vector<std::string>* warnings) {
  const ImageHeader& header = in.header();
  Texture t;
  t.source = in.source();
  t.name = std::filesystem::path(in.source()).filename().string();
  t.width = header.width;
  t.height = header.height;
  t.channels = std::min(header.channels, 4);
  t.encoding = encoding;
  size_t count = size_t(t.width) * t.height * t.channels;
  if (header.format == SampleType::kUint8) {
    t.texels_8bit.resize(count);
    in.read(t.channels, SampleType::kUint8, t.texels_8bit.data());
  } else {
    // 16-bit integer files are normalized to [0, 1] like 8-bit ones; float files keep values.
    t.texels_float.resize(count);
    in.read(t.channels, SampleType::kFloat, t.texels_float.data());
    const bool colour = encoding == TextureEncoding::kSrgb;
    const double low = colour ? 0 : -kMaxTexelValue, high = colour ? 1 : kMaxTexelValue;
    const size_t replaced = replace_unusable_texels(t.texels_float, float(low), float(high));
    if (replaced > 0 && warnings) {
      // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"[" + std::string`.)
      std::string range(1, '[');
      range.append(number_text(low)).append(", ").append(number_text(high)).append("]");
      warnings->push_back(t.source + ": " + std::to_string(replaced) + " texel value" +
                          (replaced == 1 ? " was" : "s were") + " NaN, infinite or outside " +
                          range + (colour ? " (an sRGB colour texture)" : "") +
                          " and replaced (NaN by 0, the others by the nearest bound)");
    }
  }
  return t;
}

}  // namespace

Texture read_texture(const std::string& path, TextureEncoding encoding,
                     std::vector<std::string>* warnings) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path, "texture image does not exist");
  CheckedImageInput in = CheckedImageInput::open_file(path);
  return read_pixels(in, encoding, warnings);
}

Texture decode_texture(std::span<const uint8_t> bytes, const std::string& source,
                       const std::string& format_hint, TextureEncoding encoding,
                       std::vector<std::string>* warnings) {
  CheckedImageInput in = CheckedImageInput::open_memory(bytes, source, format_hint);
  return read_pixels(in, encoding, warnings);
}

}  // namespace obscura
