// The plugin's one entry point (kImageCodecsEntryPoint): PNG, JPEG, TIFF, OpenEXR and Radiance
// HDR through their own libraries (a dozen shared libraries, a few milliseconds to load), and
// PFM. Readers it does not have, and files it leaves (open() returns nullptr), go to the
// OpenImageIO plugin (image_codecs_loader.cpp), which only those load.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "dng_codec.h"
#include "exr_codec.h"
#include "jpeg_codec.h"
#include "obscura/io/image_codecs.h"
#include "obscura/math/error.h"
#include "pfm_codec.h"
#include "png_codec.h"
#include "rgbe_codec.h"
#include "tiff_codec.h"

namespace obscura::codecs {

namespace {

std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

class NativeImageCodecs final : public ImageCodecs {
 public:
  std::unique_ptr<ImageDecoder> open(const std::string& reader, const std::string& name,
                                     bool from_memory, std::span<const uint8_t> memory,
                                     const std::string& source) const override {
    using Open = std::unique_ptr<ImageDecoder> (*)(EncodedBytes);
    Open open = reader == "png"       ? open_png
                : reader == "jpeg"    ? open_jpeg
                : reader == "tiff"    ? open_tiff
                : reader == "openexr" ? open_exr
                : reader == "hdr"     ? open_rgbe
                : reader == "pnm"     ? open_pfm  // PFM; nullptr for the rest of netpbm
                                      : nullptr;
    if (!open) return nullptr;
    return open(from_memory ? borrow_encoded_bytes(memory, source)
                            : read_encoded_file(name, source));
  }

  std::vector<unsigned char> encode(const EncodeRequest& request) const override {
    const std::string ext = lowercase_extension(request.path);
    if (ext == ".png") return encode_png(request);
    if (ext == ".jpg" || ext == ".jpeg") return encode_jpeg(request);
    if (ext == ".tif" || ext == ".tiff") return encode_tiff(request);
    if (ext == ".exr") return encode_exr(request);
    if (ext == ".hdr") return encode_rgbe(request);
    if (ext == ".dng") return encode_dng(request);
    throw Error(request.path,
                "no image writer for '" + ext + "'; expected .png, .jpg, .tif, .exr, .hdr or .dng");
  }
};

}  // namespace

}  // namespace obscura::codecs

extern "C" __attribute__((visibility("default"))) const obscura::ImageCodecs*
obscura_image_codecs_v2() {
  static const obscura::codecs::NativeImageCodecs codecs;
  return &codecs;
}
