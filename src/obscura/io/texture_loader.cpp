#include "obscura/io/texture_loader.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <memory>

#include "obscura/math/error.h"

namespace obscura {

namespace {

// Reads every pixel of an opened image into a Texture; `source` names it in messages.
Texture read_pixels(OIIO::ImageInput& in, const std::string& source, TextureEncoding encoding) {
  const OIIO::ImageSpec& spec = in.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw Error(source, "image has no pixels");
  Texture t;
  t.source = source;
  t.name = std::filesystem::path(source).filename().string();
  t.width = spec.width;
  t.height = spec.height;
  t.channels = std::min(spec.nchannels, 4);
  t.encoding = encoding;
  size_t count = size_t(t.width) * t.height * t.channels;
  bool ok;
  if (spec.format == OIIO::TypeDesc::UINT8) {
    t.texels_8bit.resize(count);
    ok = in.read_image(0, 0, 0, t.channels, OIIO::TypeDesc::UINT8, t.texels_8bit.data());
  } else {
    t.texels_float.resize(count);
    ok = in.read_image(0, 0, 0, t.channels, OIIO::TypeDesc::FLOAT, t.texels_float.data());
    // 16-bit integer files are normalized to [0, 1] like 8-bit ones; float files keep values.
  }
  if (!ok) throw Error(source, "cannot decode image: " + in.geterror());
  return t;
}

std::string extension_for(const std::string& hint) {
  if (hint == "image/png") return "png";
  if (hint == "image/jpeg") return "jpg";
  if (hint.rfind("image/", 0) == 0) return hint.substr(6);
  return hint;
}

}  // namespace

Texture read_texture(const std::string& path, TextureEncoding encoding) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(path, "texture image does not exist");
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path, "cannot read texture image: " + OIIO::geterror());
  return read_pixels(*in, path, encoding);
}

Texture decode_texture(std::span<const uint8_t> bytes, const std::string& source,
                       const std::string& format_hint, TextureEncoding encoding) {
  if (bytes.empty()) throw Error(source, "embedded image is empty");
  // OpenImageIO reads from memory through an IOProxy; the made-up file name only selects the
  // format reader.
  OIIO::Filesystem::IOMemReader memory(const_cast<uint8_t*>(bytes.data()), bytes.size());
  void* proxy = &memory;
  OIIO::ImageSpec config;
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  std::string ext = extension_for(format_hint);
  std::unique_ptr<OIIO::ImageInput> in =
      OIIO::ImageInput::open("embedded." + (ext.empty() ? std::string("png") : ext), &config);
  if (!in) throw Error(source, "cannot decode embedded image: " + OIIO::geterror());
  return read_pixels(*in, source, encoding);
}

}  // namespace obscura
