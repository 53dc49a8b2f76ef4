// The vectorised inner loop of develop()'s exact table path (see develop.h): 8 pixels at a time
// with AVX2 gathers for the table lookups, chosen at run time when the CPU has AVX2. Internal to
// develop.cpp; declared here so that the target-specific code lives in its own file.
#pragma once

#include <cstddef>
#include <cstdint>

namespace obscura::detail {

struct CodeKernel {
  const float* m;           // 3×3 display-from-working matrix, row-major
  float top;                // values are clamped to [0, top]
  const float* thresholds;  // thresholds[c + 1]: smallest value of code c + 1
  const uint16_t* buckets;  // code at the start of each 2¹⁶-float range (padded by one entry)
  float gamut_low, gamut_high;  // out-of-gamut limits in display linear
  bool clamp_input;             // min(x, 1) before the matrix (the clamp tone map)

  // Dithered mode (when curve_values is set): code = clamp(floor(encode(v)·max + ½ + offset)),
  // encode() interpolated from a table at every 2¹⁵-th float; offsets per channel for this row,
  // periodic in x with `dither_period` (a power of two ≥ 8).
  const float* curve_values = nullptr;
  const float* curve_slopes = nullptr;
  const float* dither_rows[3] = {nullptr, nullptr, nullptr};
  int dither_period = 8;
  float max_code = 255;
};

// Whether the CPU runs the AVX2 kernel.
bool has_avx2_kernel();

// Encodes whole blocks of 8 pixels from the start of `in` while they are finite, and returns how
// many pixels it did (a multiple of 8; fewer than `count` at a non-finite pixel or near the end).
// Counts out-of-gamut pixels into `out_of_gamut`.
// `x` is the column of the first pixel (for the dither pattern).
int encode_blocks_avx2(const CodeKernel& k, const float* in, int count, int x, uint8_t* out,
                       size_t& out_of_gamut);
int encode_blocks_avx2(const CodeKernel& k, const float* in, int count, int x, uint16_t* out,
                       size_t& out_of_gamut);

}  // namespace obscura::detail
