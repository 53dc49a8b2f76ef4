// Piecewise-constant distributions for importance sampling tabulated functions (environment
// maps, light selection). Values must be finite and ≥ 0; a table of zeros samples uniformly.
#pragma once

#include <span>
#include <vector>

#include "obscura/math/vector.h"

namespace obscura {

// A step function over [0, 1) with n equal cells, or a discrete choice among n items.
class Distribution1D {
 public:
  Distribution1D() = default;
  explicit Distribution1D(std::span<const float> values);

  size_t size() const { return values_.size(); }
  double integral() const { return integral_; }  // ∫ f over [0, 1), before normalization

  // x in [0, 1) with density f(x)/∫f; `*cell` receives the cell x falls in.
  float sample_continuous(float u, float* pdf, size_t* cell = nullptr) const;
  float pdf_continuous(float x) const;
  // An index with probability f_i / Σf.
  size_t sample_discrete(float u, float* probability = nullptr) const;
  float probability(size_t i) const;

 private:
  std::vector<float> values_;
  std::vector<double> cdf_;  // size n + 1, cdf_[0] = 0, cdf_[n] = 1
  double integral_ = 0;
};

// A step function over [0, 1)² (width × height cells, row-major, row 0 at v = 0), sampled by
// choosing a row from the marginal and a column from that row's conditional.
class Distribution2D {
 public:
  Distribution2D() = default;
  Distribution2D(std::span<const float> values, int width, int height);

  Point2f sample(Point2f u, float* pdf) const;
  float pdf(Point2f p) const;
  double integral() const { return marginal_.integral(); }

 private:
  std::vector<Distribution1D> rows_;
  Distribution1D marginal_;
  int width_ = 0, height_ = 0;
};

}  // namespace obscura
