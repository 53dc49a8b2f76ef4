#include "obscura/film/glare.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "obscura/film/fourier_plane.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

void check_psf(const Image& psf) {
  if (psf.width != psf.height || psf.width % 2 != 1 || (psf.channels != 1 && psf.channels != 3) ||
      psf.data.size() != size_t(psf.width) * psf.height * psf.channels)
    throw Error("glare", "the PSF must be an odd square of 1 or 3 channels; got " +
                             std::to_string(psf.width) + " × " + std::to_string(psf.height) +
                             " × " + std::to_string(psf.channels));
}

// The PSF's channel on the padded grid, its centre at (0, 0) and negative offsets wrapped to the
// far end, so that the circular convolution centres each pixel's spread on itself.
void place_kernel(FourierPlane& plane, const Image& psf, int channel) {
  const int r = psf.width / 2;
  plane.fill_zero();
  for (int dy = -r; dy <= r; ++dy) {
    double* row = plane.row((dy + plane.height()) % plane.height());
    for (int dx = -r; dx <= r; ++dx)
      row[(dx + plane.width()) % plane.width()] = psf.at(dx + r, dy + r, channel);
  }
}

}  // namespace

void validate(const GlareSettings& s) {
  if (!(s.strength >= 0 && s.strength <= 1000))
    throw Error("glare.strength", "must be in [0, 1000]; got " + number_text(s.strength));
  if (s.radius_px < 1 || s.radius_px > 4096)
    throw Error("glare.radius_px", "must be in [1, 4096]; got " + std::to_string(s.radius_px));
}

Image scale_scattered_light(const Image& psf, double strength) {
  check_psf(psf);
  Image scaled = psf;
  const int r = psf.width / 2;
  for (int c = 0; c < psf.channels; ++c) {
    double total = 0;
    for (int y = 0; y < psf.height; ++y)
      for (int x = 0; x < psf.width; ++x) {
        double value = psf.at(x, y, c) * (x == r && y == r ? 1 : strength);
        scaled.at(x, y, c) = float(value);
        total += value;
      }
    if (!(total > 0)) throw Error("glare", "the PSF holds no light");
    for (int y = 0; y < psf.height; ++y)
      for (int x = 0; x < psf.width; ++x) scaled.at(x, y, c) = float(scaled.at(x, y, c) / total);
  }
  return scaled;
}

int glare_radius_px(const GlareSettings& settings, int width, int height) {
  return std::max(1, std::min(settings.radius_px, std::max(width, height)));
}

bool convolve_with_psf(Image& image, const Image& psf, const std::atomic<bool>* cancel) {
  auto cancelled = [cancel] { return cancel && cancel->load(); };
  check_psf(psf);
  if (image.channels < 3 || image.width < 1 || image.height < 1)
    throw Error("glare", "needs an RGB image; got " + std::to_string(image.channels) + " channels");
  const int r = psf.width / 2;
  // Padding by r keeps a pixel's spread from reaching the image's far side (no wrap-around); at
  // least 2r + 1 keeps the wrapped kernel from overlapping itself.
  const int width = fft_friendly_size(std::max(image.width + r, 2 * r + 1));
  const int height = fft_friendly_size(std::max(image.height + r, 2 * r + 1));
  FourierPlane light(width, height), kernel(width, height);
  const double normalisation = 1.0 / (double(width) * height);  // the inverse is unnormalised
  // Written to a copy, so that a cancel between channels leaves the image whole.
  Image result = image;
  for (int c = 0; c < 3; ++c) {
    if (cancelled()) return false;
    if (c == 0 || psf.channels == 3) {
      place_kernel(kernel, psf, psf.channels == 3 ? c : 0);
      kernel.forward();
    }
    light.fill_zero();
    tbb::parallel_for(tbb::blocked_range<int>(0, image.height),
                      [&](const tbb::blocked_range<int>& rows) {
                        for (int y = rows.begin(); y < rows.end(); ++y)
                          for (int x = 0; x < image.width; ++x) light.row(y)[x] = image.at(x, y, c);
                      });
    light.forward();
    light.multiply(kernel, normalisation);
    light.inverse();
    tbb::parallel_for(tbb::blocked_range<int>(0, image.height),
                      [&](const tbb::blocked_range<int>& rows) {
                        for (int y = rows.begin(); y < rows.end(); ++y)
                          for (int x = 0; x < image.width; ++x)
                            result.at(x, y, c) = float(light.row(y)[x]);
                      });
  }
  if (cancelled()) return false;
  image = std::move(result);
  return true;
}

}  // namespace obscura
