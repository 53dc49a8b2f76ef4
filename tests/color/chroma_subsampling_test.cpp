// Chroma subsampling: full-resolution luma, averaged chroma.
#include "obscura/color/chroma_subsampling.h"

#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(ChromaSubsampling, PlaneSizes) {
  std::vector<uint16_t> rgb(size_t(5) * 3 * 3, 100);
  auto planes = [&](ChromaSubsampling c) {
    return to_ycbcr_planes(rgb.data(), 5, 3, 3, YcbcrMatrix::kBt709, YcbcrRange::kLimited, c);
  };
  EXPECT_EQ(planes(ChromaSubsampling::k444).cb.size(), 15u);
  EXPECT_EQ(planes(ChromaSubsampling::k422).cb.size(), 9u);  // 3 × 3
  EXPECT_EQ(planes(ChromaSubsampling::k420).cb.size(), 6u);  // 3 × 2
  EXPECT_EQ(planes(ChromaSubsampling::k420).y.size(), 15u);
}

TEST(ChromaSubsampling, FlatColourSurvivesAndLumaKeepsFullResolution) {
  // Left half dark grey, right half light grey: a pure luma edge.
  const int w = 8, h = 4;
  std::vector<uint16_t> rgb(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) rgb[(y * w + x) * 3 + k] = x < 3 ? 40 : 200;
  YcbcrPlanes p = to_ycbcr_planes(rgb.data(), w, h, 3, YcbcrMatrix::kBt709, YcbcrRange::kFull,
                                  ChromaSubsampling::k420);
  std::vector<uint16_t> back = rgb_from_ycbcr_planes(p, YcbcrMatrix::kBt709, YcbcrRange::kFull);
  EXPECT_EQ(back, rgb);  // greys have no chroma to lose: the edge at x = 3 stays sharp
}

TEST(ChromaSubsampling, ColourEdgesBlurButLumaDoesNot) {
  // A red/green edge at an odd column: 4:2:0 averages the chroma of the pair that straddles it.
  const int w = 4, h = 2;
  std::vector<uint16_t> rgb(size_t(w) * h * 3, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) rgb[(y * w + x) * 3 + (x < 1 ? 0 : 1)] = 255;
  YcbcrPlanes p = to_ycbcr_planes(rgb.data(), w, h, 3, YcbcrMatrix::kBt709, YcbcrRange::kFull,
                                  ChromaSubsampling::k420);
  std::vector<uint16_t> back = rgb_from_ycbcr_planes(p, YcbcrMatrix::kBt709, YcbcrRange::kFull);
  EXPECT_GT(std::abs(int(back[0]) - 255), 20);  // pixel 0 is no longer pure red
  EXPECT_EQ(back[3 * 3 + 1], 255);              // the all-green pair is untouched
  EXPECT_NE(p.y[0], p.y[1]);                    // luma still tells the two pixels apart
}

TEST(ChromaSubsampling, NamesAndErrors) {
  EXPECT_EQ(parse_chroma_subsampling("420"), ChromaSubsampling::k420);
  EXPECT_THROW(parse_chroma_subsampling("411"), Error);
  EXPECT_THROW(to_ycbcr_planes(nullptr, 0, 0, 3, YcbcrMatrix::kBt709, YcbcrRange::kFull,
                               ChromaSubsampling::k444),
               Error);
}

}  // namespace
}  // namespace obscura
