// JPEG through libjpeg(-turbo): grey and YCbCr/RGB files as 8-bit Y or RGB, the COM marker as
// "ImageDescription". CMYK files are left to the fallback codecs (open_jpeg returns nullptr).
#pragma once

#include <memory>
#include <vector>

#include "obscura/io/image_codecs.h"
#include "stored_image_decoder.h"

namespace obscura::codecs {

std::unique_ptr<ImageDecoder> open_jpeg(EncodedBytes encoded);
std::vector<unsigned char> encode_jpeg(const EncodeRequest& request);

}  // namespace obscura::codecs
