// Encoding through OpenImageIO into memory; see ImageCodecs::encode (obscura/io/image_codecs.h).
#pragma once

#include <vector>

#include "obscura/io/image_codecs.h"

namespace obscura::oiio {

std::vector<unsigned char> encode_image(const EncodeRequest& request);

}  // namespace obscura::oiio
