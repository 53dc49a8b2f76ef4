// libFuzzer target for image decoding as Obscura does it: the bytes are an encoded image (PNG,
// OpenEXR, Radiance HDR, PFM/PNM, JPEG, TIFF, BMP, Targa), opened from memory through
// CheckedImageInput — the header check against the decoded-size limit, then the decode — by
// decode_texture, the path a glTF's embedded images and (from a file) every texture and environment
// map take. The format is chosen from the leading magic bytes (the reader itself goes by them too;
// the name's extension matters only for Targa). An obscura::Error is the expected outcome for bad
// input; anything else escaping, a crash, a sanitizer report, a leak or > 2 GB is a finding.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>

#include "obscura/io/image_limits.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"

namespace {

std::string format_of(const uint8_t* data, size_t size) {
  auto starts = [&](const char* magic, size_t n) {
    return size >= n && std::memcmp(data, magic, n) == 0;
  };
  if (starts("\x89PNG", 4)) return "png";
  if (starts("\x76\x2f\x31\x01", 4)) return "exr";
  if (starts("#?", 2)) return "hdr";
  if (starts("PF", 2) || starts("Pf", 2)) return "pfm";
  if (starts("\xff\xd8", 2)) return "jpg";
  if (starts("II*", 3) || starts("MM\0*", 4)) return "tif";
  // Bytes with no signature reach a reader only as Targa, which has none.
  return "tga";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // 64 Ki pixels instead of the default 64 Mi: the same check and the same decoders, with decodes
  // small enough that libFuzzer's 2 GB and 10 s limits flag real defects, not large legal images,
  // and that a run is not spent clearing the megabytes a few-hundred-byte file may legally
  // declare (at 4 Mi pixels, two thirds of the time went to page faults in ASan's allocator).
  static const bool limited = (obscura::set_max_image_pixels(uint64_t(1) << 16), true);
  (void)limited;
  std::string format = format_of(data, size);
  try {
    obscura::decode_texture(std::span<const uint8_t>(data, size), "fuzz." + format, format,
                            obscura::TextureEncoding::kLinear);
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
