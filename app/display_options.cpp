#include "display_options.h"

#include <cstdio>

#include "obscura/math/error.h"
#include "option_ranges.h"
#include "usage_error.h"

namespace obscura::app {

void add_display_options(CLI::App* command, DisplayOptions& o, bool with_exposure) {
  command->add_option("--display", o.display, "Display encoding for PNG/JPEG/TIFF/Y4M output")
      ->check(CLI::IsMember(display_space_names()))
      ->capture_default_str();
  command->add_option("--tonemap", o.tonemap, "Tone mapping operator")
      ->check(CLI::IsMember({"none", "clamp", "reinhard", "aces", "hable"}))
      ->capture_default_str();
  command
      ->add_option("--reinhard-white", o.reinhard_white,
                   "Reinhard: the linear value that maps to white")
      ->check(number_in(1e-6, 1e6))
      ->capture_default_str();
  command->add_option("--gamut", o.gamut, "Out-of-gamut colours: clip, or compress chroma (OKLCh)")
      ->check(CLI::IsMember({"clip", "compress"}))
      ->capture_default_str();
  command
      ->add_option("--bits", o.bits,
                   "Bits per channel, 1-16 (above 8: 16-bit PNG/TIFF); default 8, and 16 for "
                   "rec2020-pq and rec2020-hlg")
      ->check(integer_in(1, 16));
  command->add_option("--dither", o.dither, "Dithering before quantization")
      ->check(CLI::IsMember({"none", "bayer", "blue-noise"}))
      ->capture_default_str();
  command->add_flag("--half", o.exr_half, "EXR output as 16-bit half floats");
  if (with_exposure)
    command->add_option("--exposure", o.exposure_ev, "Exposure change in stops (EV)")
        ->check(number_in(-kMaxExposureEv, kMaxExposureEv))
        ->capture_default_str();
}

ImageWriteOptions image_write_options(const DisplayOptions& o) {
  try {
    ImageWriteOptions w;
    w.display.display = parse_display_space(o.display);
    w.display.tonemap = {.op = parse_tone_map(o.tonemap), .reinhard_white = o.reinhard_white};
    w.display.gamut = parse_gamut_mapping(o.gamut);
    w.display.dither = parse_dither(o.dither);
    const bool hdr = w.display.display == DisplaySpace::kRec2020Pq ||
                     w.display.display == DisplaySpace::kRec2020Hlg;
    w.display.bits = o.bits > 0 ? o.bits : hdr ? 16 : 8;
    w.display.exposure_ev = o.exposure_ev;
    validate(w.display);
    w.exr_half = o.exr_half;
    return w;
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

void report_write(const std::string& path, const WriteReport& report, bool quiet) {
  const DevelopStats& s = report.stats;
  if (s.nan_pixels || s.inf_pixels)  // always reported: the image has a problem
    std::fprintf(stderr,
                 "warning: %s: %zu pixel(s) with NaN and %zu with Inf on the film, written as "
                 "black\n",
                 path.c_str(), s.nan_pixels, s.inf_pixels);
  if (!quiet && s.out_of_gamut_pixels)
    std::fprintf(stderr, "note: %s: %zu pixel(s) outside the display gamut\n", path.c_str(),
                 s.out_of_gamut_pixels);
}

}  // namespace obscura::app
