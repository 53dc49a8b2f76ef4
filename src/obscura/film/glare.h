// Diffraction glare as a post-process of the HDR film: every pixel's light spread by the
// optics' point-spread function (film/diffraction_psf.h), which is what turns a bright light into
// an Airy halo or a starburst. Applied to linear, scene-referred pixels before develop: on
// display values the lights have already been clipped and would lose the energy that glares.
//
// The convolution is an FFT product on a grid padded by the PSF's radius (fft_friendly_size),
// so nothing wraps around: the image is zero outside its frame, light spread beyond the frame
// leaves it and none comes in from outside (the sensor's edge), so the sum of the image is kept
// exactly only for light farther than the radius from every edge.
#pragma once

#include <atomic>

#include "obscura/film/image.h"

namespace obscura {

struct GlareSettings {
  // Scale of the light the PSF carries out of a point's own pixel: 1 is the aperture's own
  // diffraction (physical), 0 none, above 1 a stronger glare than the optics make (artistic, as
  // lenses with dirt or a star filter show). The pixel keeps its share and the PSF is normalised
  // again, so light is conserved at any strength. In [0, 1000].
  double strength = 1;
  // Where the PSF is cut off (faded over its outer quarter), in pixels; 1…4096, and at most the
  // image's larger side (glare_radius_px).
  int radius_px = 256;
};

// Throws obscura::Error naming the field and its value when out of range.
void validate(const GlareSettings& settings);

// The PSF (odd square, the point's pixel at the centre, each channel summing to 1) with its
// light outside the centre pixel scaled by `strength`, each channel normalised again.
Image scale_scattered_light(const Image& psf, double strength);

// The PSF radius worth building for a width × height image: the settings' radius, but never
// more than the image's larger side (no pixel's light can land farther away on the frame), so a
// 16 × 12 frame with radius 4096 builds a 33 × 33 PSF, not 8193 × 8193.
int glare_radius_px(const GlareSettings& settings, int width, int height);

// Convolves the first three channels of `image` with `psf` (odd square; 1 channel for all three
// or 3, one per channel). Deterministic and thread-count independent. Throws obscura::Error for
// an image with fewer than 3 channels or a PSF that is not an odd square of 1 or 3 channels.
// `cancel`, when set (from another thread) before the convolution is done, stops it: the image
// is left as it was and false returned.
bool convolve_with_psf(Image& image, const Image& psf, const std::atomic<bool>* cancel = nullptr);

}  // namespace obscura
