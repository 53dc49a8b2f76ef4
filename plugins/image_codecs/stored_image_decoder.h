// The common half of the native decoders: a header, and read() that decodes the file's own
// samples (all channels, the stored type) and converts them to what the caller asks for.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "obscura/io/image_codecs.h"

namespace obscura::codecs {

// An encoded image in memory: a file mapped here, or bytes the caller keeps alive.
struct EncodedBytes {
  std::shared_ptr<const void> mapping;  // unmaps the file
  std::span<const uint8_t> bytes;
  std::string source;  // names the image in messages
};

// Maps a whole file read-only (named `source` in messages): pages are read as the decoder
// touches them, so a file far larger than its image (trailing junk) costs no memory for the
// rest. (A file that another process truncates while it is decoded ends the process with
// SIGBUS, as with any mapped file.) Throws obscura::Error when it cannot.
EncodedBytes read_encoded_file(const std::string& path, const std::string& source);
EncodedBytes borrow_encoded_bytes(std::span<const uint8_t> bytes, const std::string& source);

class StoredImageDecoder : public ImageDecoder {
 public:
  const ImageHeader& header() const override { return header_; }
  void read(int channels, SampleType type, void* pixels) override;

 protected:
  // Decodes every channel as header().format into `pixels` (width × height × channels values).
  virtual void decode_stored(void* pixels) = 0;
  ImageHeader header_;
};

// OpenImageIO's names for a file of `channels` channels that names none (PNG, JPEG, TIFF):
// Y, YA, RGB, RGBA.
std::vector<std::string> default_channel_names(int channels);

}  // namespace obscura::codecs
