// The diffraction PSF against optics: a circular pupil gives the Airy pattern [2·J₁(v)/v]²,
// v = π·r/(λ·N), with its first dark ring at the first zero of J₁ (computed here by bisection on
// std::cyl_bessel_j, not the 1.22 the code's comments quote); a B-bladed iris throws B spikes
// (B even: opposite blades are parallel) or 2B (B odd); longer wavelengths spread wider.
#include "obscura/film/diffraction_psf.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "obscura/camera/aperture.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

PupilShape iris(int blades, double rotation_degrees = 0) {
  Aperture a{.blades = blades, .rotation_degrees = rotation_degrees};
  return [a](double x, double y) { return aperture_contains(a, {x, y}); };
}

// The first positive zero of J₁, by bisection between 3 and 4.5.
double first_zero_of_j1() {
  double lo = 3, hi = 4.5;
  for (int i = 0; i < 60; ++i) {
    double mid = 0.5 * (lo + hi);
    (std::cyl_bessel_j(1.0, lo) * std::cyl_bessel_j(1.0, mid) <= 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// The Airy intensity at v: [2·J₁(v)/v]², 1 at v = 0.
double airy(double v) {
  if (v < 1e-9) return 1;
  double a = 2 * std::cyl_bessel_j(1.0, v) / v;
  return a * a;
}

// Bilinear sample of a one-channel image at pixel-centre coordinates (x, y).
double sample(const Image& im, double x, double y) {
  int i = int(std::floor(x)), j = int(std::floor(y));
  double fx = x - i, fy = y - j;
  auto at = [&](int u, int v) { return double(im.at(u, v, 0)); };
  return (at(i, j) * (1 - fx) + at(i + 1, j) * fx) * (1 - fy) +
         (at(i, j + 1) * (1 - fx) + at(i + 1, j + 1) * fx) * fy;
}

// The spikes crossing an annulus around the centre: the PSF averaged over radii in [inner, outer]
// at each direction, and the directions (degrees, [0, 360)) of the brightest sample of each
// run of directions above a fifth of the brightest average.
std::vector<double> spikes_in_annulus(const Image& psf, double inner, double outer) {
  const int steps = 1440;
  const double c = psf.width / 2;
  std::vector<double> ring(steps);
  for (int k = 0; k < steps; ++k) {
    double t = 2 * kPi * k / steps;
    for (double r = inner; r <= outer; r += 0.5)
      ring[k] += sample(psf, c + r * std::cos(t), c - r * std::sin(t));
  }
  const double threshold = 0.2 * *std::max_element(ring.begin(), ring.end());
  int start = 0;  // begin at a direction below the threshold, so no run is split in two
  while (ring[start] >= threshold) ++start;
  std::vector<double> found;
  for (int n = 0; n < steps;) {
    if (ring[(start + n) % steps] < threshold) {
      ++n;
      continue;
    }
    int best = (start + n) % steps;
    for (; n < steps && ring[(start + n) % steps] >= threshold; ++n)
      if (ring[(start + n) % steps] > ring[best]) best = (start + n) % steps;
    found.push_back(360.0 * best / steps);
  }
  std::sort(found.begin(), found.end());
  return found;
}

TEST(DiffractionPsf, CircularPupilHasItsFirstDarkRingWhereJ1VanishesWithin2Percent) {
  const double wavelength_nm = 550, f_number = 8, pitch_mm = 0.0005;
  const int radius = 40;
  Image psf = monochromatic_psf({.pupil = iris(0),
                                 .f_number = f_number,
                                 .pixel_width_mm = pitch_mm,
                                 .pixel_height_mm = pitch_mm},
                                wavelength_nm, radius);
  ASSERT_EQ(psf.width, 2 * radius + 1);
  // The radial profile along +x from the centre; its first local minimum, refined by a parabola.
  std::vector<double> profile;
  for (int k = 0; k <= radius; ++k) profile.push_back(psf.at(radius + k, radius, 0));
  int k = 1;
  while (k + 1 < int(profile.size()) &&
         !(profile[k] < profile[k - 1] && profile[k] <= profile[k + 1]))
    ++k;
  ASSERT_LT(k + 1, int(profile.size()));
  double a = profile[k - 1], b = profile[k], c = profile[k + 1];
  double minimum_px = k + 0.5 * (a - c) / (a - 2 * b + c);
  const double lambda_n_mm = wavelength_nm * 1e-6 * f_number;
  const double expected_mm = first_zero_of_j1() / kPi * lambda_n_mm;  // 1.2197·λ·N
  EXPECT_NEAR(minimum_px * pitch_mm, expected_mm, 0.02 * expected_mm);
}

TEST(DiffractionPsf, CircularPupilFollowsTheAiryProfile) {
  const double wavelength_nm = 500, f_number = 4, pitch_mm = 0.0004;
  const int radius = 24;
  Image psf = monochromatic_psf({.pupil = iris(0),
                                 .f_number = f_number,
                                 .pixel_width_mm = pitch_mm,
                                 .pixel_height_mm = pitch_mm},
                                wavelength_nm, radius);
  // The reference: the Airy intensity averaged over each pixel (8 × 8 points), relative to the
  // centre pixel's, as the PSF's own values are.
  const double lambda_n_mm = wavelength_nm * 1e-6 * f_number;
  auto pixel_mean = [&](int i, int j) {
    double sum = 0;
    for (int sy = 0; sy < 8; ++sy)
      for (int sx = 0; sx < 8; ++sx) {
        double x = (i + (sx + 0.5) / 8 - 0.5) * pitch_mm, y = (j + (sy + 0.5) / 8 - 0.5) * pitch_mm;
        sum += airy(kPi * std::hypot(x, y) / lambda_n_mm);
      }
    return sum / 64;
  };
  const double centre = psf.at(radius, radius, 0), reference_centre = pixel_mean(0, 0);
  for (int k = 0; k <= 16; ++k) {
    double expected = pixel_mean(k, 0) / reference_centre;
    EXPECT_NEAR(psf.at(radius + k, radius, 0) / centre, expected, 0.01) << "pixel " << k;
    EXPECT_NEAR(psf.at(radius, radius + k, 0) / centre, expected, 0.01) << "pixel " << k;
  }
}

TEST(DiffractionPsf, BladedIrisThrowsOneSpikePerBladeWhenEvenTwoWhenOdd) {
  for (auto [blades, spikes] : {std::pair{6, 6}, {5, 10}, {7, 14}, {8, 8}}) {
    Image psf = monochromatic_psf(
        {.pupil = iris(blades), .f_number = 8, .pixel_width_mm = 0.002, .pixel_height_mm = 0.002},
        550, 64);
    std::vector<double> found = spikes_in_annulus(psf, 30, 50);
    EXPECT_EQ(int(found.size()), spikes) << blades << " blades";
    for (size_t i = 0; i < found.size(); ++i)  // evenly spaced
      EXPECT_NEAR(found[(i + 1) % found.size()] - found[i] + (i + 1 == found.size() ? 360 : 0),
                  360.0 / spikes, 2)
          << blades << " blades";
    if (blades == 6) {
      // Spikes run across the blades: with a vertex on +x, two edges face straight up and down.
      bool vertical = false;
      for (double angle : found) vertical |= std::abs(angle - 90) < 2 || std::abs(angle - 270) < 2;
      EXPECT_TRUE(vertical);
    }
  }
}

TEST(DiffractionPsf, ChannelsSumToOneAndRedSpreadsWiderThanBlue) {
  Image psf = rgb_psf(
      {.pupil = iris(0), .f_number = 11, .pixel_width_mm = 0.002, .pixel_height_mm = 0.002}, 32);
  ASSERT_EQ(psf.channels, 3);
  // The mean squared radius of each channel: the pattern scales with λ, so red's exceeds blue's.
  double second_moment[3] = {}, sum[3] = {};
  for (int y = 0; y < psf.height; ++y)
    for (int x = 0; x < psf.width; ++x)
      for (int c = 0; c < 3; ++c) {
        double r2 = (x - 32.0) * (x - 32.0) + (y - 32.0) * (y - 32.0);
        sum[c] += psf.at(x, y, c);
        second_moment[c] += psf.at(x, y, c) * std::min(r2, 100.0);  // the core, not the cut tail
      }
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1, 1e-5);
  EXPECT_GT(second_moment[0], 1.2 * second_moment[2]);
  EXPECT_GT(second_moment[1], second_moment[2]);
}

// Pixels thousands of λ·N wide (a wide aperture on a film of a few pixels) hold all but the Airy
// pattern's encircled-energy tail in the centre pixel: the fraction of an Airy pattern beyond
// radius r is J₀(v)² + J₁(v)² at v = π·r/(λ·N) (Rayleigh), and the square pixel contains the
// disc of radius half a pixel. The wings would need a pupil grid far beyond the largest one.
TEST(DiffractionPsf, PixelsFarWiderThanThePatternKeepItsEnergyInTheCentre) {
  const double f_number = 1, pixel_mm = 5;
  Image psf = rgb_psf({.pupil = iris(0),
                       .f_number = f_number,
                       .pixel_width_mm = pixel_mm,
                       .pixel_height_mm = pixel_mm},
                      4);
  ASSERT_EQ(psf.width, 9);
  const double v = kPi * 0.5 * pixel_mm / (780e-6 * f_number);  // the longest wavelength: widest
  const double beyond =
      std::pow(std::cyl_bessel_j(0.0, v), 2) + std::pow(std::cyl_bessel_j(1.0, v), 2);
  ASSERT_LT(beyond, 1e-3);
  for (int c = 0; c < 3; ++c) EXPECT_GE(psf.at(4, 4, c), 1 - beyond) << "channel " << c;
}

// A cancel set before the work starts stops it: no pattern, no PSF.
TEST(DiffractionPsf, StopsWhenCancelled) {
  std::atomic<bool> cancel{true};
  EXPECT_TRUE(pupil_pattern(iris(6), 4096, 0.5, &cancel).intensity.empty());
  Image psf =
      rgb_psf({.pupil = iris(0), .f_number = 2, .pixel_width_mm = 0.05, .pixel_height_mm = 0.05},
              64, &cancel);
  EXPECT_TRUE(psf.data.empty());
}

TEST(DiffractionPsf, RejectsBadOptics) {
  DiffractionOptics good{
      .pupil = iris(0), .f_number = 8, .pixel_width_mm = 0.01, .pixel_height_mm = 0.01};
  DiffractionOptics bad = good;
  bad.f_number = 0;
  EXPECT_THROW(rgb_psf(bad, 8), Error);
  bad = good;
  bad.pixel_height_mm = -1;
  EXPECT_THROW(rgb_psf(bad, 8), Error);
  EXPECT_THROW(rgb_psf(good, 0), Error);
  EXPECT_THROW(monochromatic_psf(good, 0, 8), Error);
  bad = good;
  bad.pupil = [](double, double) { return false; };
  EXPECT_THROW(rgb_psf(bad, 8), Error);
}

}  // namespace
}  // namespace obscura
