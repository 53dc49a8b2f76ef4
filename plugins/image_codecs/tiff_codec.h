// TIFF through libtiff: grey or RGB with or without alpha, 8/16-bit integers, 16/32-bit floats,
// interleaved, in strips or tiles, any compression libtiff decodes. Other layouts (palettes,
// CMYK, YCbCr, separate planes, 1-bit…) are left to the fallback codecs: open_tiff returns
// nullptr for them.
#pragma once

#include <memory>
#include <vector>

#include "obscura/io/image_codecs.h"
#include "stored_image_decoder.h"

namespace obscura::codecs {

std::unique_ptr<ImageDecoder> open_tiff(EncodedBytes encoded);
std::vector<unsigned char> encode_tiff(const EncodeRequest& request);

}  // namespace obscura::codecs
