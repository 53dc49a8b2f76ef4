// The one way Obscura opens an image for reading, from a file or from bytes in memory: the
// header is read and checked against the decoded-size limit (image_limits.h) before any pixel
// is decoded. Textures, environment maps, glTF images, read_image() and the image fuzz target
// all go through it.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace obscura {

// Reads from bytes in memory for OpenImageIO. (OpenImageIO 2.4's IOMemReader copies past its
// buffer when a reader asks for an offset beyond the end, which a corrupt file makes OpenEXR
// do: found by fuzz/image_fuzz.cpp.) Reads past the end return fewer bytes, never more.
//
// It is an IOMemReader (proxy type "memreader") because some OpenImageIO 2.4 readers — JPEG —
// accept no other proxy: they take the whole buffer from it (libjpeg's bounded memory source)
// instead of calling read().
class BoundedMemoryReader final : public OIIO::Filesystem::IOMemReader {
 public:
  explicit BoundedMemoryReader(std::span<const uint8_t> bytes)
      : IOMemReader(bytes.data(), bytes.size()), bytes_(bytes) {}
  size_t read(void* buffer, size_t size) override;
  size_t pread(void* buffer, size_t size, int64_t offset) override;
  size_t size() const override { return bytes_.size(); }

 private:
  std::span<const uint8_t> bytes_;
};

class CheckedImageInput {
 public:
  // Opens an image file. Throws obscura::Error naming the file when it is missing, not a regular
  // file, unreadable, or over the limits.
  static CheckedImageInput open_file(const std::string& path);
  // Opens an encoded image (PNG, JPEG, …) held in `bytes`, which must outlive the reader.
  // `source` names it in messages. The format is the one the leading bytes announce (PNG, JPEG,
  // OpenEXR, Radiance HDR, PFM/PNM, TIFF, BMP); `format_hint`, a file extension
  // ("tga") or MIME type, matters only for Targa, which has no signature. Both opens refuse
  // bytes that are none of these, so no other OpenImageIO reader ever sees them.
  static CheckedImageInput open_memory(std::span<const uint8_t> bytes, const std::string& source,
                                       const std::string& format_hint);

  const OIIO::ImageSpec& spec() const { return input_->spec(); }
  const std::string& source() const { return source_; }
  // The reader's format: "openexr", "png", …
  const char* format_name() const { return input_->format_name(); }

  // Decodes subimage 0's channels [0, channels) as `type` into `pixels`, which holds
  // width × height × channels values. Throws obscura::Error naming the source on failure.
  void read(int channels, OIIO::TypeDesc type, void* pixels);

 private:
  CheckedImageInput(std::string source, std::unique_ptr<BoundedMemoryReader> memory,
                    std::unique_ptr<OIIO::ImageInput> input);

  std::string source_;
  std::unique_ptr<BoundedMemoryReader> memory_;  // the proxy input_ reads through
  std::unique_ptr<OIIO::ImageInput> input_;
};

}  // namespace obscura
