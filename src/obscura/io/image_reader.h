// The one way Obscura opens an image for reading, from a file or from bytes in memory: the
// header is read and checked against the decoded-size limit (image_limits.h) before any pixel
// is decoded. Textures, environment maps, glTF images, read_image() and the image fuzz target
// all go through it.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "obscura/io/image_codecs.h"

namespace obscura {

class CheckedImageInput {
 public:
  // Opens an image file. Throws obscura::Error naming the file when it is missing, not a regular
  // file, unreadable, or over the limits.
  static CheckedImageInput open_file(const std::string& path);
  // Opens an encoded image (PNG, JPEG, …) held in `bytes`, which must outlive the reader.
  // `source` names it in messages. The format is the one the leading bytes announce (PNG, JPEG,
  // OpenEXR, Radiance HDR, PFM/PNM, TIFF, BMP); `format_hint`, a file extension
  // ("tga") or MIME type, matters only for Targa, which has no signature. Both opens refuse
  // bytes that are none of these, so no other reader of the codecs ever sees them.
  static CheckedImageInput open_memory(std::span<const uint8_t> bytes, const std::string& source,
                                       const std::string& format_hint);

  const ImageHeader& header() const { return decoder_->header(); }
  const std::string& source() const { return source_; }
  // The reader's format: "openexr", "png", …
  const std::string& format_name() const { return decoder_->header().format_name; }

  // Decodes subimage 0's channels [0, channels) as `type` into `pixels`, which holds
  // width × height × channels values. Throws obscura::Error naming the source on failure.
  void read(int channels, SampleType type, void* pixels) { decoder_->read(channels, type, pixels); }

 private:
  CheckedImageInput(std::string source, std::unique_ptr<ImageDecoder> decoder);

  std::string source_;
  std::unique_ptr<ImageDecoder> decoder_;  // from the image codecs plugin
};

}  // namespace obscura
