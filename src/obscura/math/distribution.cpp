#include "obscura/math/distribution.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "obscura/math/safe_index.h"

namespace obscura {

Distribution1D::Distribution1D(std::span<const float> values)
    : values_(values.begin(), values.end()), cdf_(values.size() + 1, 0.0) {
  size_t n = values_.size();
  // A weight of NaN counts as 0 and +∞ as the largest float: summed in double, the CDF stays
  // finite, so it never divides ∞ by ∞ into NaN cells that every sample then falls through.
  for (float& v : values_) v = v > 0 ? std::min(v, std::numeric_limits<float>::max()) : 0.f;
  for (size_t i = 0; i < n; ++i) cdf_[i + 1] = cdf_[i] + values_[i] / double(n);
  integral_ = cdf_[n];
  if (integral_ <= 0) {  // nothing to prefer: uniform
    for (size_t i = 0; i <= n; ++i) cdf_[i] = double(i) / n;
    std::fill(values_.begin(), values_.end(), 1.f);
  } else {
    for (double& c : cdf_) c /= integral_;
  }
  cdf_[n] = 1;
}

size_t Distribution1D::sample_discrete(float u, float* probability_out) const {
  // The last cell whose cdf start is ≤ u, skipping empty cells.
  auto it = std::upper_bound(cdf_.begin(), cdf_.end(), double(u));
  size_t i = std::clamp<size_t>(size_t(it - cdf_.begin()), 1, values_.size()) - 1;
  if (probability_out) *probability_out = probability(i);
  return i;
}

float Distribution1D::probability(size_t i) const {
  return float(cdf_[i + 1] - cdf_[i]);
}

float Distribution1D::sample_continuous(float u, float* pdf, size_t* cell) const {
  size_t i = sample_discrete(u);
  double width = cdf_[i + 1] - cdf_[i];
  double offset = width > 0 ? (u - cdf_[i]) / width : 0.5;
  if (cell) *cell = i;
  if (pdf) *pdf = float(width * values_.size());  // probability / cell width
  return std::min(float((i + std::clamp(offset, 0.0, 1.0)) / values_.size()), 0x1.fffffep-1f);
}

float Distribution1D::pdf_continuous(float x) const {
  size_t i = size_t(clamp_or_low(x * float(values_.size()), 0.f, float(values_.size() - 1)));
  return probability(i) * float(values_.size());
}

Distribution2D::Distribution2D(std::span<const float> values, int width, int height)
    : width_(width), height_(height) {
  std::vector<float> row_integrals(height);
  rows_.reserve(height);
  for (int y = 0; y < height; ++y) {
    rows_.emplace_back(values.subspan(size_t(y) * width, width));
    row_integrals[y] = float(rows_.back().integral());
  }
  marginal_ = Distribution1D(row_integrals);
}

Point2f Distribution2D::sample(Point2f u, float* pdf) const {
  float pdf_v, pdf_u;
  size_t row;
  float v = marginal_.sample_continuous(u.y, &pdf_v, &row);
  float x = rows_[row].sample_continuous(u.x, &pdf_u);
  *pdf = pdf_u * pdf_v;
  return {x, v};
}

float Distribution2D::pdf(Point2f p) const {
  size_t row = size_t(clamp_or_low(p.y * float(height_), 0.f, float(height_ - 1)));
  return marginal_.pdf_continuous(p.y) * rows_[row].pdf_continuous(p.x);
}

}  // namespace obscura
