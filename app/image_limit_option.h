// --max-image-pixels N: the decoded-size limit for every image a command reads (see
// obscura/io/image_limits.h), on each command that reads images.
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

// Registers --max-image-pixels on `command`; given, it sets the process's limit while the
// command line is parsed, before the command runs, taking precedence over
// OBSCURA_MAX_IMAGE_PIXELS.
void add_max_image_pixels_option(CLI::App* command);

}  // namespace obscura::app
