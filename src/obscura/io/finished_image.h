// Whether an image file is finished work, for resuming (sequences, datasets): files are renamed
// into place only when complete (io/atomic_file.h), so what is there is either whole or damaged
// from outside (a copy cut short, a full disk).
#pragma once

#include <string>

namespace obscura {

// Whether `path` holds an image of width × height not marked partial ("obscura:partial") whose
// every pixel reads back; false for a missing, empty, truncated or unreadable file.
bool finished_image_exists(const std::string& path, int width, int height);

}  // namespace obscura
