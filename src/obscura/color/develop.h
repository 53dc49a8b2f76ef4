// Developing the film: linear, scene-referred RGB → the integer codes a display or file holds.
//
// Per pixel, in order: non-finite values are counted and replaced by 0 (black: a NaN or Inf is a
// numerical failure, and a black dot shows it without spreading it), exposure (×2^EV), tone mapping
// (in the working space, linear Rec.709), the matrix to the display's primaries, gamut handling
// (clip, or CSS Color 4 chroma compression), the display's transfer function, then quantization to
// N bits with optional dithering.
//
// The common case (no exposure change, clamp or no tone map, clip, ≤ 8 bits, no dither) runs a
// table-driven path that is exact to the standard: each channel's code comes from comparing the
// linear value with the precomputed linear thresholds between codes, found by bisection on the
// double-precision transfer function, so no approximation of the curve is involved.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "obscura/color/display.h"
#include "obscura/color/matrix3.h"
#include "obscura/color/rgb.h"

namespace obscura {

// A read-only view of linear pixels: width × height × channels floats, row-major. Channels: 1
// (grey), 3 (RGB) or 4 (RGBA; alpha is quantized linearly, not tone mapped or encoded).
struct LinearPixels {
  const float* data = nullptr;
  int width = 0, height = 0, channels = 0;
};

struct DevelopStats {
  size_t nan_pixels = 0;           // pixels with at least one NaN
  size_t inf_pixels = 0;           // pixels with at least one ±Inf (and no NaN)
  size_t out_of_gamut_pixels = 0;  // after tone mapping: a channel < 0 or above display white
  DevelopStats& operator+=(const DevelopStats& o);
};

struct DisplayImage {
  int width = 0, height = 0, channels = 0;  // 3 or 4
  int bits = 8;
  DisplaySpace display = DisplaySpace::kSrgb;
  std::vector<uint16_t> codes;  // N-bit codes, row-major, interleaved
  DevelopStats stats;
};

// Develops an image; uses all cores (oneTBB). Throws obscura::Error for invalid settings or an
// unsupported channel count.
DisplayImage develop(const LinearPixels& image, const DisplaySettings& settings);

// 1 where a pixel falls outside the display's gamut after exposure and tone mapping, else 0.
std::vector<uint8_t> out_of_gamut_mask(const LinearPixels& image, const DisplaySettings& settings);

// The per-row engine behind develop(), for callers that manage their own threads and buffers
// (benchmarks, video writers). Construction builds the tables (a few ms); encode_rgb_row is
// thread-safe.
class DisplayEncoder {
 public:
  explicit DisplayEncoder(const DisplaySettings& settings);
  ~DisplayEncoder();
  DisplayEncoder(const DisplayEncoder&) = delete;
  DisplayEncoder& operator=(const DisplayEncoder&) = delete;

  // `count` packed RGB pixels of row `y` starting at column `x0` → packed codes. The uint8_t
  // form requires bits ≤ 8.
  void encode_rgb_row(const float* rgb, int count, int x0, int y, uint8_t* out,
                      DevelopStats& stats) const;
  void encode_rgb_row(const float* rgb, int count, int x0, int y, uint16_t* out,
                      DevelopStats& stats) const;

  // Whether the exact table path applies (see the file comment).
  bool uses_fast_path() const;
  // Whether working-space linear RGB falls outside the display's gamut after exposure and tone
  // mapping (a channel below 0 or above the display's white).
  bool out_of_gamut(Rgb working_linear) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace obscura
