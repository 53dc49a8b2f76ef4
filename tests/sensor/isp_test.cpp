// Demosaicing against an analytic reference: a mosaic sampled from colour planes that vary
// linearly across the image is reconstructed exactly by both bilinear interpolation and
// Malvar–He–Cutler (whose Laplacian correction vanishes on a linear signal), for every CFA.
#include "obscura/sensor/isp.h"

#include <gtest/gtest.h>

#include <cmath>

namespace obscura {
namespace {

double plane(int c, int x, int y) {
  return 10 + 3 * c + (0.5 + c) * x - (0.25 * c - 0.7) * y;
}

TEST(Demosaic, LinearColourPlanesAreExactAwayFromTheEdges) {
  const int w = 24, h = 18;
  for (CfaPattern cfa :
       {CfaPattern::kRggb, CfaPattern::kBggr, CfaPattern::kGrbg, CfaPattern::kGbrg}) {
    Image mosaic(w, h, 1);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) mosaic.at(x, y, 0) = float(plane(cfa_color(cfa, x, y), x, y));
    for (DemosaicMethod method : {DemosaicMethod::kBilinear, DemosaicMethod::kMalvar}) {
      const Image rgb = demosaic(mosaic, cfa, method);
      for (int y = 2; y < h - 2; ++y)
        for (int x = 2; x < w - 2; ++x)
          for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(rgb.at(x, y, c), plane(c, x, y), 1e-4)
                << cfa_pattern_name(cfa) << " " << int(method) << " at " << x << "," << y;
    }
  }
}

TEST(Demosaic, MonochromeIsCopied) {
  Image mosaic(3, 2, 1);
  mosaic.data = {1, 2, 3, 4, 5, 6};
  const Image rgb = demosaic(mosaic, CfaPattern::kMonochrome, DemosaicMethod::kMalvar);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(rgb.at(2, 1, c), 6.f);
}

}  // namespace
}  // namespace obscura
