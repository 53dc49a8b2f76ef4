// Finds and loads the image codecs plugin (image_codecs.h) the first time an image is read or
// written, once per process.
#pragma once

#include <string>
#include <vector>

#include "obscura/io/image_codecs.h"

namespace obscura {

// The loaded codecs. The first call loads libobscura_image_codecs.so from the first of
// image_codecs_search_dirs() that holds it; throws obscura::Error naming every folder it looked
// in (and why each failed) when none does. Later calls return the same codecs, or the same error.
const ImageCodecs& image_codecs();

// Where the plugin is looked for, in order: $OBSCURA_PLUGIN_DIR when set (an override wins over
// what is found by position); the folder of the binary that holds this library (the executable,
// or the Python extension module); that folder's ../<install lib dir> (the installed layout:
// bin/obscura finds lib/…); and the build tree the library was built in.
std::vector<std::string> image_codecs_search_dirs();

}  // namespace obscura
