#include "obscura/io/texture_loader.h"

#include <algorithm>
#include <filesystem>

#include "obscura/io/image_reader.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

// Reads every pixel of an opened, checked image into a Texture.
Texture read_pixels(CheckedImageInput& in, TextureEncoding encoding) {
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
  }
  return t;
}

}  // namespace

Texture read_texture(const std::string& path, TextureEncoding encoding) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path, "texture image does not exist");
  CheckedImageInput in = CheckedImageInput::open_file(path);
  return read_pixels(in, encoding);
}

Texture decode_texture(std::span<const uint8_t> bytes, const std::string& source,
                       const std::string& format_hint, TextureEncoding encoding) {
  CheckedImageInput in = CheckedImageInput::open_memory(bytes, source, format_hint);
  return read_pixels(in, encoding);
}

}  // namespace obscura
