// PNG through libpng: 8 and 16 bits, grey, grey + alpha, RGB, RGBA (palettes and fewer bits are
// expanded to 8), tEXt/zTXt/iTXt chunks as text attributes ("Description" as "ImageDescription").
#pragma once

#include <memory>
#include <vector>

#include "obscura/io/image_codecs.h"
#include "stored_image_decoder.h"

namespace obscura::codecs {

std::unique_ptr<ImageDecoder> open_png(EncodedBytes encoded);
std::vector<unsigned char> encode_png(const EncodeRequest& request);

}  // namespace obscura::codecs
