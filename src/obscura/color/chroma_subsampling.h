// Chroma subsampling: Y′CbCr planes with full-resolution luma and colour differences at half
// the width (4:2:2) or half the width and height (4:2:0). The eye resolves detail in intensity
// far better than in colour, which is why video stores colour at a quarter of the samples.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "obscura/color/ycbcr.h"

namespace obscura {

enum class ChromaSubsampling { k444, k422, k420 };
std::string chroma_subsampling_name(ChromaSubsampling c);             // "444", "422", "420"
ChromaSubsampling parse_chroma_subsampling(const std::string& name);  // throws obscura::Error

// 8-bit planes. Chroma samples are the box average of the 2×1 or 2×2 pixels they cover (sited
// at their centre, as JPEG and Y4M's "420jpeg" expect); odd sizes round the chroma size up.
struct YcbcrPlanes {
  int width = 0, height = 0;
  int chroma_width = 0, chroma_height = 0;
  std::vector<uint8_t> y, cb, cr;
};

// From 8-bit encoded R′G′B′ codes (`channels` per pixel, the first three used).
YcbcrPlanes to_ycbcr_planes(const uint16_t* rgb8, int width, int height, int channels,
                            YcbcrMatrix matrix, YcbcrRange range, ChromaSubsampling subsampling);
// Back to 8-bit R′G′B′ (3 channels), each chroma sample replicated over the pixels it covers.
std::vector<uint16_t> rgb_from_ycbcr_planes(const YcbcrPlanes& planes, YcbcrMatrix matrix,
                                            YcbcrRange range);

}  // namespace obscura
