// Linear least squares: the x that minimizes ‖A x − b‖₂ for a tall, full-rank A (rows ≥ columns),
// solved by Householder QR on A with its columns scaled to unit length first. QR never forms AᵀA,
// so it loses half as many digits as the normal equations do on an ill-conditioned basis (powers
// of a variable, as in a polynomial fit).
#pragma once

#include <vector>

namespace obscura {

struct LeastSquaresProblem {
  int columns = 0;
  std::vector<double> a;  // row by row: rows × columns
  std::vector<double> b;  // one per row

  int rows() const { return int(b.size()); }
  // Appends the row (a, b); `row` has `columns` entries.
  void add_row(const std::vector<double>& row, double value);
};

// The minimizer x (columns entries). Throws obscura::Error when there are fewer rows than
// columns, a value is not finite, or the columns are dependent (rank deficient to 1e-12).
std::vector<double> solve_least_squares(const LeastSquaresProblem& problem);

}  // namespace obscura
