// Portable float map (PFM, the float member of the netpbm family): "PF" (RGB) or "Pf" (grey),
// white-space separated width, height and scale (negative: little-endian), one white-space byte,
// then rows of 32-bit floats bottom to top. The other netpbm formats (P1–P6) are left to the
// fallback codecs: open_pfm returns nullptr for them. (Obscura writes PFM itself: image_io.cpp.)
#pragma once

#include <memory>

#include "obscura/io/image_codecs.h"
#include "stored_image_decoder.h"

namespace obscura::codecs {

std::unique_ptr<ImageDecoder> open_pfm(EncodedBytes encoded);

}  // namespace obscura::codecs
