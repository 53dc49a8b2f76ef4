// A real 2-D grid and its discrete Fourier transform, in place, for convolutions of images
// (diffraction glare, film/glare.h; the point-spread function of a pupil, film/diffraction_psf.h).
//
// FFTW (double precision) computes it as 1-D transforms: real-to-complex along each row, then
// complex along each column of the half spectrum (width/2 + 1 columns, the rest follows from
// conjugate symmetry). The rows, and the columns in blocks of eight, are handed to oneTBB's
// threads, each running one of the same few plans: every 1-D transform is the same arithmetic
// whichever thread runs it, so results are bit-identical for any thread count (FFTW's own
// threaded plans make no such promise). Double precision keeps the transform's round-off near
// 1e-16 of the brightest pixel, so a sun does not lift the noise floor of a dark sky.
#pragma once

#include <complex>
#include <memory>

namespace obscura {

// The smallest n ≥ `at_least` whose only prime factors are 2, 3, 5 and 7 (fast FFT sizes).
int fft_friendly_size(int at_least);

class FourierPlane {
 public:
  // Precondition: width ≥ 2 and height ≥ 1 (throws obscura::Error otherwise). Starts all zero.
  FourierPlane(int width, int height);
  ~FourierPlane();
  FourierPlane(FourierPlane&&) noexcept;
  FourierPlane& operator=(FourierPlane&&) noexcept;

  int width() const { return width_; }
  int height() const { return height_; }
  // Columns of the half spectrum: width/2 + 1.
  int spectrum_width() const { return width_ / 2 + 1; }

  // The real grid: meaningful before forward() and after inverse().
  double* row(int y) { return data_.get() + size_t(y) * 2 * pitch_; }
  const double* row(int y) const { return data_.get() + size_t(y) * 2 * pitch_; }
  // The half spectrum: meaningful after forward(). Row y holds frequencies (0…width/2, y).
  std::complex<double>* spectrum_row(int y) {
    return reinterpret_cast<std::complex<double>*>(row(y));
  }
  const std::complex<double>* spectrum_row(int y) const {
    return reinterpret_cast<const std::complex<double>*>(row(y));
  }

  void fill_zero();
  // Real grid → half spectrum: F(u, v) = Σ f(x, y)·e^(−2πi(ux/W + vy/H)).
  void forward();
  // Half spectrum → real grid, unnormalised: the result is width·height times the input of
  // forward().
  void inverse();
  // Spectrum ← spectrum × other's spectrum × scale (a circular convolution once inverted).
  // Precondition: the same size.
  void multiply(const FourierPlane& other, double scale = 1);

 private:
  struct Plans;
  struct FreeFftw {
    void operator()(double* p) const;
  };
  int width_, height_;
  int pitch_;  // complex numbers per row: spectrum_width() rounded up to a block of columns
  std::unique_ptr<double, FreeFftw> data_;
  std::unique_ptr<Plans> plans_;
};

}  // namespace obscura
