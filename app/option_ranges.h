// Range checks for numeric command-line options, applied while the command line is parsed.
//
// CLI11 would convert "5x", "nan", "1e308" or "-1" in its own ways (or not at all); these
// validators read the option's text themselves, whole and strictly, so that every bad value is a
// usage error (exit 2) that names the option, the value and the range it must lie in.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

namespace obscura::app {

// The most pixels along either side of an image, and in the whole image (2^28, about 268
// megapixels: a float RGBA film of that size already takes several GB).
inline constexpr int64_t kMaxImageSidePx = 65536;
inline constexpr int64_t kMaxImagePixels = int64_t(1) << 28;

inline constexpr int64_t kMaxRasterSamples = int64_t(1) << 16;  // --raster-samples
inline constexpr int64_t kMaxTraceDepth = 1024;                 // --max-depth
inline constexpr int64_t kMaxThreads = 4096;
inline constexpr double kMaxTimeLimitS = 1e7;  // about four months
// 2^±64 keeps any radiance a scene can hold (≤ 1e15 or so) finite in a float film.
inline constexpr double kMaxExposureEv = 64;
inline constexpr double kMaxFilterRadiusPx = 16;

// A whole decimal number (no sign for lo ≥ 0, no exponent, no fraction) in [lo, hi].
CLI::Validator integer_in(int64_t lo, int64_t hi);
// A whole non-negative decimal number that fits in 64 bits (random seeds).
CLI::Validator unsigned_64();
// A finite decimal number in [lo, hi] (fractions and exponents allowed; nan and inf are not).
CLI::Validator number_in(double lo, double hi);
// The same, or "inf" (a far plane at infinity, as scene files default to).
CLI::Validator number_in_or_infinity(double lo, double hi);

// Throws UsageError (when `from_command_line`) or obscura::Error unless width × height is within
// the limits above.
void check_image_size(int64_t width, int64_t height, bool from_command_line);

}  // namespace obscura::app
