// The second plugin's one entry point (kOiioCodecsEntryPoint): OpenImageIO's readers for the
// formats the native plugin does not decode (BMP, Targa, PNM other than PFM, and the rarer layouts
// of TIFF and JPEG). OpenImageIO pulls in some 250 shared libraries (~0.25 s, ~100 MB), so only a
// process that reads such a file loads it. It writes nothing: every format Obscura writes has a
// native encoder.
#include "obscura/io/image_codecs.h"
#include "obscura/math/error.h"
#include "oiio_decoder.h"

namespace {

class OiioImageCodecs final : public obscura::ImageCodecs {
 public:
  std::unique_ptr<obscura::ImageDecoder> open(const std::string& reader, const std::string& name,
                                              bool from_memory, std::span<const uint8_t> memory,
                                              const std::string& source) const override {
    return obscura::oiio::open_image(reader, name, from_memory, memory, source);
  }
  std::vector<unsigned char> encode(const obscura::EncodeRequest& request) const override {
    throw obscura::Error(request.path, "the OpenImageIO plugin encodes nothing");
  }
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const obscura::ImageCodecs*
obscura_oiio_codecs_v2() {
  static const OiioImageCodecs codecs;
  return &codecs;
}
