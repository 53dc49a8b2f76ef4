// Pixel filters: published values of the kernels, and filter importance sampling against the
// filter it samples (weighted sample moments equal the filter's own moments).
#include "obscura/camera/pixel_filter.h"

#include <cmath>

#include <gtest/gtest.h>

#include "obscura/math/error.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

TEST(PixelFilter, MitchellNetravaliPublishedValues) {
  // With B = C = 1/3 on its natural support [−2, 2]: k(0) = (6 − 2B)/6 = 8/9, k(1) = B/6 = 1/18,
  // k(2) = 0 (Mitchell & Netravali 1988, eq. 8).
  PixelFilter m = MitchellFilter{};
  EXPECT_NEAR(evaluate(m, {0, 0}), (8.0 / 9) * (8.0 / 9), 1e-12);
  EXPECT_NEAR(evaluate(m, {1, 0}), (1.0 / 18) * (8.0 / 9), 1e-12);
  EXPECT_NEAR(evaluate(m, {2, 0}), 0, 1e-12);
  // Its negative lobe: k(1.5) = [(−B − 6C)·1.5³ + (6B + 30C)·1.5² + (−12B − 48C)·1.5 + 8B + 24C] /
  // 6 = (−7.875 + 27 − 30 + 10.6667) / 6 = −0.0347222.
  EXPECT_NEAR(evaluate(m, {1.5, 0}) / (8.0 / 9), -0.0347222222, 1e-9);
}

TEST(PixelFilter, TentBoxAndGaussianShapes) {
  EXPECT_DOUBLE_EQ(evaluate(TentFilter{.radius_px = 2}, {1, 0}), 0.5);
  EXPECT_DOUBLE_EQ(evaluate(TentFilter{.radius_px = 2}, {1, 1}), 0.25);
  EXPECT_DOUBLE_EQ(evaluate(BoxFilter{}, {0.49, -0.49}), 1);
  EXPECT_DOUBLE_EQ(evaluate(BoxFilter{}, {0.51, 0}), 0);
  GaussianFilter g{.radius_px = 1.5, .sigma_px = 0.5};
  EXPECT_NEAR(evaluate(g, {1.5, 0}), 0, 1e-15);  // reaches zero at the radius
  double e = std::exp(-4.5);                     // exp(−r²/2σ²)
  EXPECT_NEAR(evaluate(g, {0.5, 0}), (std::exp(-0.5) - e) * (1 - e), 1e-12);
}

// E[w·h(x)] / E[w] must equal ∫f·h / ∫f. For box (radius ½) and tent (radius 1) the second
// moments are analytic: 1/12 and 1/6. For the tabulated filters the reference integrals come
// from evaluate() by quadrature (sampling against evaluation).
double weighted_second_moment(const PixelFilter& f, int samples) {
  FilterSampler sampler(f);
  Pcg32 rng(9);
  double sum_w = 0, sum_wx2 = 0;
  for (int i = 0; i < samples; ++i) {
    FilterSample s = sampler.sample({rng.next_float(), rng.next_float()});
    EXPECT_LE(std::abs(s.offset_px.x), filter_radius_px(f) + 1e-12);
    EXPECT_LE(std::abs(s.offset_px.y), filter_radius_px(f) + 1e-12);
    sum_w += s.weight;
    sum_wx2 += s.weight * s.offset_px.x * s.offset_px.x;
  }
  return sum_wx2 / sum_w;
}

double quadrature_second_moment(const PixelFilter& f) {
  double r = filter_radius_px(f), num = 0, den = 0;
  constexpr int kSteps = 20000;
  for (int i = 0; i < kSteps; ++i) {
    double x = -r + (i + 0.5) * 2 * r / kSteps;
    double v = evaluate(f, {x, 0});
    num += v * x * x;
    den += v;
  }
  return num / den;
}

TEST(PixelFilter, ImportanceSamplingReproducesTheFilter) {
  EXPECT_NEAR(weighted_second_moment(BoxFilter{}, 100000), 1.0 / 12, 1e-3);
  EXPECT_NEAR(weighted_second_moment(TentFilter{}, 100000), 1.0 / 6, 2e-3);
  for (PixelFilter f : {PixelFilter(GaussianFilter{}), PixelFilter(MitchellFilter{})}) {
    double expected = quadrature_second_moment(f);
    EXPECT_NEAR(weighted_second_moment(f, 200000), expected, 0.01 * expected + 1e-3)
        << filter_name(f);
  }
}

TEST(PixelFilter, MitchellWeightsCarryTheLobesSign) {
  FilterSampler sampler(MitchellFilter{});
  bool negative = false;
  Pcg32 rng(1);
  for (int i = 0; i < 5000 && !negative; ++i)
    negative = sampler.sample({rng.next_float(), rng.next_float()}).weight < 0;
  EXPECT_TRUE(negative);
  EXPECT_EQ(FilterSampler(BoxFilter{}).sample({0.3, 0.8}).weight, 1.0);
}

TEST(PixelFilter, MakeByNameAndRejectBadRadius) {
  EXPECT_EQ(filter_name(make_pixel_filter("gaussian")), "gaussian");
  EXPECT_DOUBLE_EQ(filter_radius_px(make_pixel_filter("tent", 1.5)), 1.5);
  EXPECT_THROW(make_pixel_filter("lanczos"), Error);
  EXPECT_THROW(make_pixel_filter("box", -1), Error);
}

}  // namespace
}  // namespace obscura
