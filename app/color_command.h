// `obscura color`: colour conversions and spectral colours on the command line
// (convert, wavelength, temperature, spaces).
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

void add_color_command(CLI::App& app);

}  // namespace obscura::app
