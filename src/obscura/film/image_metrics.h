// How far one image is from another: mean squared error, its root, PSNR and the largest error,
// per channel and over all, and the mean signed difference (a bias). What `obscura image diff`
// prints, the reference tests assert and the benchmarks report.
#pragma once

#include <cstddef>
#include <vector>

#include "obscura/film/image.h"

namespace obscura {

struct ImageDifference {
  int width = 0, height = 0, channels = 0;
  // Per channel, over the pixels (non-finite differences skipped but counted in the mean, as 0).
  std::vector<double> squared_error;  // Σ (a − b)²
  std::vector<double> max_abs;        // max |a − b|
  std::vector<double> sum;            // Σ (a − b)
  size_t non_finite = 0;              // differences that were ±∞ or NaN

  double pixels() const { return double(width) * height; }
  double mse(int channel) const { return squared_error[size_t(channel)] / pixels(); }
  double rmse(int channel) const;
  double mse() const;  // over every channel
  double rmse() const;
  double max_abs_all() const;
  double mean_difference() const;  // mean of a − b over every channel: the bias of a
};

// Compares the first `channels` channels of `a` and `b` (−1: all; then both must have as many);
// they must have the same size. Throws obscura::Error otherwise.
ImageDifference compare_images(const Image& a, const Image& b, int channels = -1);

// The root mean squared error over the first `channels` channels (−1: all).
double rmse(const Image& a, const Image& b, int channels = -1);

// Peak signal-to-noise ratio in dB for a mean squared error, with peak value `peak`: +∞ for 0.
double psnr(double mse, double peak = 1);

// Per pixel, the largest |a − b| over the channels (non-finite ones skipped): one channel.
// Same preconditions as compare_images.
Image pixel_max_abs_difference(const Image& a, const Image& b, int channels = -1);

}  // namespace obscura
