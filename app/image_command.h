// `obscura image`: convert an image file (develop linear images for display, or re-encode), and
// compare two images (MSE, RMSE, PSNR, max error per channel, optional heat map).
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

void add_image_command(CLI::App& app);

}  // namespace obscura::app
