#include "obscura/film/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

namespace {

std::string shape(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
         std::to_string(image.channels);
}

// The channels compared; throws for images that cannot be compared.
int compared_channels(const Image& a, const Image& b, int channels) {
  if (a.width != b.width || a.height != b.height)
    throw Error("image comparison",
                "cannot compare a " + shape(a) + " image with a " + shape(b) + " one");
  if (channels < 0) {
    if (a.channels != b.channels)
      throw Error("image comparison",
                  "cannot compare a " + shape(a) + " image with a " + shape(b) + " one");
    return a.channels;
  }
  if (channels == 0 || channels > a.channels || channels > b.channels)
    throw Error("image comparison", "cannot compare " + std::to_string(channels) +
                                        " channels of a " + shape(a) + " and a " + shape(b) +
                                        " image");
  return channels;
}

}  // namespace

double ImageDifference::rmse(int channel) const {
  return std::sqrt(mse(channel));
}

double ImageDifference::mse() const {
  double total = 0;
  for (double s : squared_error) total += s;
  return total / (pixels() * channels);
}

double ImageDifference::rmse() const {
  return std::sqrt(mse());
}

double ImageDifference::max_abs_all() const {
  double largest = 0;
  for (double m : max_abs) largest = std::max(largest, m);
  return largest;
}

double ImageDifference::mean_difference() const {
  double total = 0;
  for (double s : sum) total += s;
  return total / (pixels() * channels);
}

ImageDifference compare_images(const Image& a, const Image& b, int channels) {
  ImageDifference d;
  d.width = a.width;
  d.height = a.height;
  d.channels = compared_channels(a, b, channels);
  d.squared_error.assign(size_t(d.channels), 0);
  d.max_abs.assign(size_t(d.channels), 0);
  d.sum.assign(size_t(d.channels), 0);
  const size_t pixels = size_t(a.width) * a.height;
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < d.channels; ++c) {
      double diff = double(a.data[p * a.channels + c]) - b.data[p * b.channels + c];
      if (!std::isfinite(diff)) {
        ++d.non_finite;
        continue;
      }
      d.squared_error[size_t(c)] += diff * diff;
      d.max_abs[size_t(c)] = std::max(d.max_abs[size_t(c)], std::abs(diff));
      d.sum[size_t(c)] += diff;
    }
  return d;
}

double rmse(const Image& a, const Image& b, int channels) {
  return compare_images(a, b, channels).rmse();
}

double psnr(double mse, double peak) {
  return mse > 0 ? 10 * std::log10(peak * peak / mse) : std::numeric_limits<double>::infinity();
}

Image pixel_max_abs_difference(const Image& a, const Image& b, int channels) {
  const int compared = compared_channels(a, b, channels);
  Image errors(a.width, a.height, 1);
  const size_t pixels = size_t(a.width) * a.height;
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < compared; ++c) {
      double diff = double(a.data[p * a.channels + c]) - b.data[p * b.channels + c];
      if (std::isfinite(diff)) errors.data[p] = std::max(errors.data[p], float(std::abs(diff)));
    }
  return errors;
}

}  // namespace obscura
