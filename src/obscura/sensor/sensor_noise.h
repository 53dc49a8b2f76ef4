// The random draws of the sensor's noise, each a pure function of (key, pixel, draw number) —
// counter-based, so a pixel's noise is the same whichever thread, tile or process computes it.
#pragma once

#include <cstdint>

namespace obscura {

class NoiseStream {
 public:
  // `key` names the noise source and its seed (fixed pattern or frame), `pixel` the pixel's
  // index in the full frame.
  NoiseStream(uint64_t key, uint64_t pixel) : key_(key), pixel_(pixel) {}

  // Uniform in (0, 1) with 53 random bits: never 0, so logarithms are finite.
  double uniform();
  // Standard normal (Box–Muller on two uniforms).
  double normal();
  // Poisson-distributed count of mean `mean` ≥ 0: by inversion below 10, by Hörmann's
  // transformed rejection with squeeze ("PTRS", 1993) from 10 on; exact in distribution for
  // every mean (no normal approximation), so the photon-transfer test sees variance = mean.
  double poisson(double mean);

 private:
  uint64_t key_, pixel_;
  uint64_t counter_ = 0;
};

}  // namespace obscura
