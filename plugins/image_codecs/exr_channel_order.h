// The order in which an OpenEXR file's channels are handed out. The file keeps them sorted by
// name (B, G, R); OpenImageIO, which wrote and read Obscura's files before, hands out the
// unlayered channels first, then each layer ("albedo.R") in name order, and within each R, G, B,
// A first, then the rest in the file's order. Obscura's own files (R G B [A|W], X Y Z, Z, id,
// named layers) read back in the order they were written.
#pragma once

#include <string>
#include <vector>

namespace obscura::codecs {

std::vector<std::string> exr_channel_order(std::vector<std::string> names_in_file_order);

}  // namespace obscura::codecs
