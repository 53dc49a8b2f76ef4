// Loads the image codecs plugin (image_codecs.h) the first time an image is read or written,
// once per process.
#pragma once

#include "obscura/io/image_codecs.h"

namespace obscura {

// The loaded codecs. The first call loads libobscura_image_codecs.so (plugin_loader.h: where it
// is looked for); throws obscura::Error naming every place it looked (and why each failed) when
// none holds it. Later calls return the same codecs, or the same error. A read that those codecs
// leave (BMP, Targa, PNM other than PFM…) loads libobscura_oiio_codecs.so, OpenImageIO, the same
// way.
const ImageCodecs& image_codecs();

}  // namespace obscura
