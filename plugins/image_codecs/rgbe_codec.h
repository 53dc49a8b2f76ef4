// Radiance HDR (RGBE, Greg Ward's format; no Debian library reads it): the header lines, the
// "-Y H +X W" resolution line (and "+Y H +X W", flipped), and scanlines flat, in the old
// run-length form, or in the adaptive form of 8 ≤ width < 32768. A pixel is mantissas R, G, B
// and a shared exponent E: each channel is mantissa × 2^(E − 136), and 0 when E is 0. Written
// files are "32-bit_rle_rgbe" with adaptive run-length scanlines.
#pragma once

#include <memory>
#include <vector>

#include "obscura/io/image_codecs.h"
#include "stored_image_decoder.h"

namespace obscura::codecs {

std::unique_ptr<ImageDecoder> open_rgbe(EncodedBytes encoded);
std::vector<unsigned char> encode_rgbe(const EncodeRequest& request);

}  // namespace obscura::codecs
