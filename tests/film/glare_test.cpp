// Glare by FFT convolution: light conserved, nothing wrapping round the frame, the same image
// for any thread count, and the strength scaling the scattered light as documented. The
// references are sums and a direct (spatial) convolution written here.
#include "obscura/film/glare.h"

#include <tbb/global_control.h>

#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "obscura/camera/aperture.h"
#include "obscura/film/diffraction_psf.h"
#include "obscura/math/error.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

Image test_psf(int radius, int blades = 6) {
  Aperture a{.blades = blades, .rotation_degrees = 10};
  return rgb_psf({.pupil =
                      [a](double x, double y) {
                        return aperture_contains(a, {x, y});
                      },
                  .f_number = 8,
                  .pixel_width_mm = 0.003,
                  .pixel_height_mm = 0.003},
                 radius);
}

// Random HDR values, a few very bright, only farther than `margin` from every edge.
Image random_image(int width, int height, int margin, uint64_t seed) {
  Image image(width, height, 3);
  Pcg32 rng(seed);
  for (int y = margin; y < height - margin; ++y)
    for (int x = margin; x < width - margin; ++x)
      for (int c = 0; c < 3; ++c) {
        float v = rng.next_float();
        image.at(x, y, c) = v > 0.99f ? 1e4f * v : v;
      }
  return image;
}

double channel_sum(const Image& image, int c) {
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum;
}

TEST(Glare, PreservesEachChannelsEnergyTo1e3) {
  const int radius = 12;
  Image image = random_image(70, 50, radius, 1);
  Image glared = image;
  convolve_with_psf(glared, test_psf(radius));
  for (int c = 0; c < 3; ++c) {
    double before = channel_sum(image, c), after = channel_sum(glared, c);
    EXPECT_NEAR(after / before, 1, 1e-3) << "channel " << c;
  }
  // And it did spread light: some pixel changed by more than rounding.
  double largest_change = 0;
  for (size_t i = 0; i < image.data.size(); ++i)
    largest_change = std::max(largest_change, double(std::abs(glared.data[i] - image.data[i])));
  EXPECT_GT(largest_change, 1);
}

TEST(Glare, EqualsTheDirectConvolution) {
  const int radius = 5;
  Image psf = test_psf(radius, 5);
  Image image = random_image(23, 17, 0, 2);
  Image glared = image;
  convolve_with_psf(glared, psf);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        double direct = 0;  // Σ image(x − d)·psf(d), zero outside the frame
        for (int dy = -radius; dy <= radius; ++dy)
          for (int dx = -radius; dx <= radius; ++dx) {
            int sx = x - dx, sy = y - dy;
            if (sx < 0 || sy < 0 || sx >= image.width || sy >= image.height) continue;
            direct += double(image.at(sx, sy, c)) * psf.at(dx + radius, dy + radius, c);
          }
        ASSERT_NEAR(glared.at(x, y, c), direct, 1e-4 * (1 + std::abs(direct))) << x << "," << y;
      }
}

TEST(Glare, BrightEdgePixelDoesNotWrapToTheOppositeEdge) {
  const int radius = 16;
  const Image psf = test_psf(radius, 0);
  Image left(64, 40, 3), top(64, 40, 3);
  left.set_rgb(0, 20, {1e6f, 1e6f, 1e6f});
  top.set_rgb(30, 0, {1e6f, 1e6f, 1e6f});
  convolve_with_psf(left, psf);
  convolve_with_psf(top, psf);
  EXPECT_GT(left.at(2, 20, 1), 1);  // spread to its neighbours...
  EXPECT_GT(top.at(30, 2, 1), 1);
  for (int c = 0; c < 3; ++c) {
    for (int y = 0; y < left.height; ++y)
      for (int x = left.width - radius; x < left.width; ++x)  // ...not round to the right edge
        ASSERT_LT(std::abs(left.at(x, y, c)), 1e-6f) << x << "," << y;
    for (int x = 0; x < top.width; ++x)
      for (int y = top.height - radius; y < top.height; ++y)  // nor to the bottom
        ASSERT_LT(std::abs(top.at(x, y, c)), 1e-6f) << x << "," << y;
  }
}

TEST(Glare, SameImageForAnyThreadCount) {
  Image psf = test_psf(20);
  Image source = random_image(200, 120, 0, 3);
  Image one = source, many = source;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    convolve_with_psf(one, psf);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 4);
    convolve_with_psf(many, psf);
  }
  ASSERT_EQ(one.data.size(), many.data.size());
  EXPECT_EQ(std::memcmp(one.data.data(), many.data.data(), one.data.size() * sizeof(float)), 0);
  Image psf_one, psf_many;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    psf_one = test_psf(20);
  }
  EXPECT_EQ(std::memcmp(psf_one.data.data(), psf.data.data(), psf.data.size() * sizeof(float)), 0);
}

TEST(Glare, StrengthScalesTheScatteredLight) {
  Image psf = test_psf(10);
  const int r = 10;
  for (double strength : {0.0, 0.5, 3.0}) {
    Image scaled = scale_scattered_light(psf, strength);
    for (int c = 0; c < 3; ++c) {
      // The centre keeps its light p₀; the rest (1 − p₀) is scaled: p₀ / (p₀ + k·(1 − p₀)).
      double p0 = psf.at(r, r, c);
      EXPECT_NEAR(scaled.at(r, r, c), p0 / (p0 + strength * (1 - p0)), 1e-5);
      EXPECT_NEAR(channel_sum(scaled, c), 1, 1e-5);
    }
  }
  // Strength 0 leaves the image as it was.
  Image image = random_image(30, 20, 0, 4), glared = image;
  convolve_with_psf(glared, scale_scattered_light(psf, 0));
  for (size_t i = 0; i < image.data.size(); ++i)
    ASSERT_NEAR(glared.data[i], image.data[i], 1e-3 * (1 + std::abs(image.data[i])));
}

TEST(Glare, RejectsBadInput) {
  Image image(8, 8, 3);
  EXPECT_THROW(convolve_with_psf(image, Image(4, 4, 3)), Error);  // even
  EXPECT_THROW(convolve_with_psf(image, Image(5, 3, 3)), Error);  // not square
  EXPECT_THROW(convolve_with_psf(image, Image(5, 5, 2)), Error);
  Image grey(8, 8, 1);
  EXPECT_THROW(convolve_with_psf(grey, Image(5, 5, 3)), Error);
  EXPECT_THROW(validate(GlareSettings{.strength = -1}), Error);
  EXPECT_THROW(validate(GlareSettings{.radius_px = 0}), Error);
}

}  // namespace
}  // namespace obscura
