// Command-line options for how the linear film becomes display codes (--display, --tonemap,
// --bits, --dither, --gamut, --reinhard-white), shared by `render` and `image convert`.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "obscura/io/image_io.h"

namespace obscura::app {

struct DisplayOptions {
  std::string display = "srgb";
  std::string tonemap = "clamp";
  std::string gamut = "clip";
  std::string dither = "none";
  int bits = 0;  // 0: 8, or 16 for the HDR displays (rec2020-pq, rec2020-hlg)
  float reinhard_white = 4;
  float exposure_ev = 0;  // only where --exposure is registered (image convert)
  bool exr_half = false;
};

// Registers the options on `command`; with `with_exposure`, also --exposure EV.
void add_display_options(CLI::App* command, DisplayOptions& options, bool with_exposure = false);

// The library settings; throws UsageError for values out of range.
ImageWriteOptions image_write_options(const DisplayOptions& options);

// Prints what a write had to repair (NaN/Inf pixels) and how much was out of gamut, on stderr.
void report_write(const std::string& path, const WriteReport& report, bool quiet);

}  // namespace obscura::app
