// Diffraction by the camera's aperture: the point-spread function (PSF) that spreads every point
// of light on the sensor into an Airy pattern (a circular iris) or a starburst (a bladed one).
//
// Fraunhofer (far-field) diffraction: the field the lens brings to its focus is the Fourier
// transform of the pupil, so a point imaged at distance z behind a pupil P of diameter D forms
//   PSF_λ(x) ∝ |F{P}(x / (λ·z))|²,
// which depends on x only through x / (λ·N) with N = z / D the working f-number. The pattern is
// computed once, in those units, as the squared magnitude of the pupil's FFT (pupil_pattern),
// and each wavelength's PSF on the sensor is that pattern stretched by λ·N and integrated over
// each pixel (exactly, through a summed-area table of the pattern). A circular pupil gives the
// Airy pattern [2·J₁(v)/v]² with v = π·r/(λ·N): the first dark ring at r = 1.22·λ·N.
//
// The colour PSF sums the wavelengths 380–780 nm in 10 nm bands, each weighted by the CIE 1931
// observer (color/cie_tables.h) turned into linear Rec.709 (the film's space): channel c of
// band b weighs max(0, (RGB_from_XYZ · x̄ȳz̄_b)_c). The colour-matching functions' small negative
// lobes are clipped, as a PSF cannot be negative. Each channel is normalised to unit sum, so the
// glare moves light without adding or removing any.
//
// The pattern is cut off at `radius_px` pixels and faded to zero over the outer quarter of that
// radius (a hard edge would show as a ring or square around bright lights); the energy beyond,
// about 2/(π²·r/(λ·N)) of the total for a circle, is given back to the rest by the
// normalisation. It is also cut where a 4096² pupil grid reaches (very wide apertures on large
// pixels, where the whole pattern is a fraction of a pixel anyway); when that is within the
// centre pixel the PSF is the centre pixel alone, found without computing the pattern.
#pragma once

#include <atomic>

#include <functional>
#include <vector>

#include "obscura/film/image.h"

namespace obscura {

// The aperture's shape on the unit disk (its size comes from the f-number): true where light
// passes; convex (a disc or a regular polygon), which the antialiasing of its edge assumes. A
// predicate, so that film/ need not know the camera's blades (render/camera_glare.h hands over the
// camera's aperture). x right, y up, seen from the sensor.
using PupilShape = std::function<bool(double x, double y)>;

struct DiffractionOptics {
  PupilShape pupil;
  double f_number = 8;  // the working f-number z / D (image distance over pupil diameter), > 0
  double pixel_width_mm = 0.01, pixel_height_mm = 0.01;  // the sensor's pixel pitch, > 0
};

// |F{pupil}|² on a size × size grid, centre at (size/2, size/2), samples `spacing` apart in units
// of λ·N; sums to 1. The pupil spans spacing·size samples of its own grid, so spacing ≤ ½ keeps
// the pattern free of aliasing.
struct PupilPattern {
  int size = 0;
  double spacing = 0;
  std::vector<double> intensity;  // row-major; row index grows along −y (down the image)
};
// Throws obscura::Error for size < 16 or spacing outside (0, ½]. `cancel`, once set, stops the
// work between rows (and before and after the FFT): an empty pattern is returned.
PupilPattern pupil_pattern(const PupilShape& pupil, int size, double spacing,
                           const std::atomic<bool>* cancel = nullptr);

// The PSF at one wavelength as a one-channel image of (2·radius_px + 1)² pixels, the point's own
// pixel at the centre; sums to 1. Throws obscura::Error for invalid optics or radius < 1.
Image monochromatic_psf(const DiffractionOptics& optics, double wavelength_nm, int radius_px);
// The colour PSF (R, G, B), each channel summing to 1. `cancel`, once set (from another thread, a
// signal handler), stops the work between rows of the PSF: an empty image (no pixels) is returned.
Image rgb_psf(const DiffractionOptics& optics, int radius_px,
              const std::atomic<bool>* cancel = nullptr);

}  // namespace obscura
