// OpenEXR through the OpenEXR library: scanline or tiled (the first part, the top level), half,
// float or uint channels, string attributes as text ("comments" as "ImageDescription"), and
// OpenImageIO's channel order (see exr_channel_order.h). Deep files are reported deep (and then
// refused by the caller); subsampled channels are left to the fallback codecs (nullptr).
#pragma once

#include <memory>
#include <vector>

#include "obscura/io/image_codecs.h"
#include "stored_image_decoder.h"

namespace obscura::codecs {

std::unique_ptr<ImageDecoder> open_exr(EncodedBytes encoded);
std::vector<unsigned char> encode_exr(const EncodeRequest& request);

}  // namespace obscura::codecs
