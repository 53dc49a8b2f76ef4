// A blue-noise threshold mask, generated at start-up with Ulichney's void-and-cluster method
// (1993): a dot pattern whose dots are as evenly spread as possible at every density, so that
// a dithered image shows fine, high-frequency noise without the visible grid of Bayer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obscura {

struct BlueNoiseMask {
  int size = 0;                 // the mask is size × size and tiles the plane
  std::vector<uint32_t> ranks;  // a permutation of 0 … size²−1

  // The threshold of a pixel, uniform in (0, 1): (rank + ½) / size².
  float threshold(int x, int y) const {
    return (float(ranks[size_t(y) * size + x]) + 0.5f) / float(size * size);
  }
};

// Generates a mask. Deterministic for a given size and seed. Cost grows as size⁴
// (64: a few tens of ms).
BlueNoiseMask generate_blue_noise(int size, uint64_t seed = 1);

// The 64×64 mask used by Dither::kBlueNoise, generated once on first use.
const BlueNoiseMask& blue_noise_mask();

}  // namespace obscura
