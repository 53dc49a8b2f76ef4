// Image metrics against values worked by hand.
#include "obscura/film/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(ImageMetrics, ErrorsOfAKnownDifference) {
  // Two pixels, two channels: differences (0.1, −0.2) and (0.3, 0).
  Image a(2, 1, 2), b(2, 1, 2);
  a.data = {0.6f, 0.3f, 1.0f, 0.25f};
  b.data = {0.5f, 0.5f, 0.7f, 0.25f};
  const ImageDifference d = compare_images(a, b);
  EXPECT_NEAR(d.mse(0), (0.01 + 0.09) / 2, 1e-7);
  EXPECT_NEAR(d.mse(1), 0.04 / 2, 1e-7);
  EXPECT_NEAR(d.mse(), 0.14 / 4, 1e-7);
  EXPECT_NEAR(d.rmse(), std::sqrt(0.035), 1e-7);
  EXPECT_NEAR(d.max_abs[0], 0.3, 1e-7);
  EXPECT_NEAR(d.max_abs_all(), 0.3, 1e-7);
  EXPECT_NEAR(d.mean_difference(), (0.1 - 0.2 + 0.3) / 4, 1e-7);
  EXPECT_NEAR(psnr(d.mse()), 10 * std::log10(1 / 0.035), 1e-5);
  EXPECT_NEAR(psnr(0.01, 2), 10 * std::log10(4 / 0.01), 1e-9);
  EXPECT_TRUE(std::isinf(psnr(0)));
  EXPECT_EQ(d.non_finite, 0u);
}

TEST(ImageMetrics, FirstChannelsOnlyAndNonFiniteSkipped) {
  Image rgb(1, 1, 3), rgba(1, 1, 4);
  rgb.data = {1, 1, std::numeric_limits<float>::infinity()};
  rgba.data = {0.5f, 1, 0, 1};
  EXPECT_NEAR(rmse(rgb, rgba, 2), std::sqrt(0.25 / 2), 1e-7);
  const ImageDifference d = compare_images(rgb, rgba, 3);
  EXPECT_EQ(d.non_finite, 1u);
  EXPECT_NEAR(pixel_max_abs_difference(rgb, rgba, 3).at(0, 0, 0), 0.5, 1e-7);
}

TEST(ImageMetrics, ImagesThatCannotBeComparedAreErrors) {
  EXPECT_THROW(compare_images(Image(2, 2, 3), Image(2, 1, 3)), Error);
  EXPECT_THROW(compare_images(Image(2, 2, 3), Image(2, 2, 4)), Error);
  EXPECT_THROW(compare_images(Image(2, 2, 3), Image(2, 2, 4), 4), Error);
  EXPECT_THROW(compare_images(Image(2, 2, 3), Image(2, 2, 4), 0), Error);
}

}  // namespace
}  // namespace obscura
