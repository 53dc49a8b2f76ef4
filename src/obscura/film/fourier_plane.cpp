#include "obscura/film/fourier_plane.h"

#include <fftw3.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <mutex>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

namespace {

// Columns are transformed this many at a time: 8 complex doubles are two cache lines of each
// row, and a block's start keeps the alignment the plans were made for.
constexpr int kColumnBlock = 8;

// FFTW's planner is not thread-safe (its execution is): plans are made and destroyed under this.
std::mutex& planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

fftw_complex* as_fftw(double* p) {
  return reinterpret_cast<fftw_complex*>(p);
}

}  // namespace

int fft_friendly_size(int at_least) {
  for (int n = std::max(at_least, 1);; ++n) {
    int m = n;
    for (int p : {2, 3, 5, 7})
      while (m % p == 0) m /= p;
    if (m == 1) return n;
  }
}

struct FourierPlane::Plans {
  fftw_plan row_forward = nullptr, row_inverse = nullptr;
  fftw_plan column_forward = nullptr, column_inverse = nullptr;
  ~Plans() {
    std::lock_guard lock(planner_mutex());
    for (fftw_plan p : {row_forward, row_inverse, column_forward, column_inverse})
      if (p) fftw_destroy_plan(p);
  }
};

void FourierPlane::FreeFftw::operator()(double* p) const {
  fftw_free(p);
}

FourierPlane::FourierPlane(int width, int height) : width_(width), height_(height) {
  if (width < 2 || height < 1)
    throw Error("FourierPlane", "needs at least 2 × 1 samples; got " + std::to_string(width) +
                                    " × " + std::to_string(height));
  pitch_ = (spectrum_width() + kColumnBlock - 1) / kColumnBlock * kColumnBlock;
  size_t doubles = size_t(height) * 2 * pitch_;
  data_.reset(static_cast<double*>(fftw_malloc(doubles * sizeof(double))));
  if (!data_)
    throw Error("FourierPlane", "out of memory for " + std::to_string(doubles) + " doubles");
  fill_zero();
  plans_ = std::make_unique<Plans>();
  double* base = data_.get();
  const int n_columns[] = {height};
  std::lock_guard lock(planner_mutex());
  // FFTW_ESTIMATE plans without touching the data; execution later passes each row or block.
  plans_->row_forward = fftw_plan_dft_r2c_1d(width, base, as_fftw(base), FFTW_ESTIMATE);
  plans_->row_inverse = fftw_plan_dft_c2r_1d(width, as_fftw(base), base, FFTW_ESTIMATE);
  plans_->column_forward =
      fftw_plan_many_dft(1, n_columns, kColumnBlock, as_fftw(base), nullptr, pitch_, 1,
                         as_fftw(base), nullptr, pitch_, 1, FFTW_FORWARD, FFTW_ESTIMATE);
  plans_->column_inverse =
      fftw_plan_many_dft(1, n_columns, kColumnBlock, as_fftw(base), nullptr, pitch_, 1,
                         as_fftw(base), nullptr, pitch_, 1, FFTW_BACKWARD, FFTW_ESTIMATE);
  if (!plans_->row_forward || !plans_->row_inverse || !plans_->column_forward ||
      !plans_->column_inverse)
    throw Error("FourierPlane", "FFTW could not plan a " + std::to_string(width) + " × " +
                                    std::to_string(height) + " transform");
}

FourierPlane::~FourierPlane() = default;
FourierPlane::FourierPlane(FourierPlane&&) noexcept = default;
FourierPlane& FourierPlane::operator=(FourierPlane&&) noexcept = default;

void FourierPlane::fill_zero() {
  std::fill(data_.get(), data_.get() + size_t(height_) * 2 * pitch_, 0.0);
}

void FourierPlane::forward() {
  tbb::parallel_for(tbb::blocked_range<int>(0, height_), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y)
      fftw_execute_dft_r2c(plans_->row_forward, row(y), as_fftw(row(y)));
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, pitch_ / kColumnBlock),
                    [&](const tbb::blocked_range<int>& r) {
                      for (int b = r.begin(); b < r.end(); ++b) {
                        fftw_complex* block = as_fftw(row(0)) + size_t(b) * kColumnBlock;
                        fftw_execute_dft(plans_->column_forward, block, block);
                      }
                    });
}

void FourierPlane::inverse() {
  tbb::parallel_for(tbb::blocked_range<int>(0, pitch_ / kColumnBlock),
                    [&](const tbb::blocked_range<int>& r) {
                      for (int b = r.begin(); b < r.end(); ++b) {
                        fftw_complex* block = as_fftw(row(0)) + size_t(b) * kColumnBlock;
                        fftw_execute_dft(plans_->column_inverse, block, block);
                      }
                    });
  tbb::parallel_for(tbb::blocked_range<int>(0, height_), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y)
      fftw_execute_dft_c2r(plans_->row_inverse, as_fftw(row(y)), row(y));
  });
}

void FourierPlane::multiply(const FourierPlane& other, double scale) {
  if (other.width_ != width_ || other.height_ != height_)
    throw Error("FourierPlane::multiply", "the planes differ in size");
  tbb::parallel_for(tbb::blocked_range<int>(0, height_), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y) {
      std::complex<double>* a = spectrum_row(y);
      const std::complex<double>* b = other.spectrum_row(y);
      for (int u = 0; u < spectrum_width(); ++u) a[u] *= b[u] * scale;
    }
  });
}

}  // namespace obscura
