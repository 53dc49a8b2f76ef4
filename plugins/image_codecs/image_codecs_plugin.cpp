// The plugin's one entry point (kImageCodecsEntryPoint): OpenImageIO's codecs as ImageCodecs.
#include "obscura/io/image_codecs.h"
#include "oiio_decoder.h"
#include "oiio_encoder.h"

namespace {

class OiioImageCodecs final : public obscura::ImageCodecs {
 public:
  std::unique_ptr<obscura::ImageDecoder> open(const std::string& reader, const std::string& name,
                                              bool from_memory, std::span<const uint8_t> memory,
                                              const std::string& source) const override {
    return obscura::oiio::open_image(reader, name, from_memory, memory, source);
  }
  std::vector<unsigned char> encode(const obscura::EncodeRequest& request) const override {
    return obscura::oiio::encode_image(request);
  }
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const obscura::ImageCodecs*
obscura_image_codecs_v1() {
  static const OiioImageCodecs codecs;
  return &codecs;
}
