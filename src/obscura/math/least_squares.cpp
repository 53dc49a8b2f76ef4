#include "obscura/math/least_squares.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

void LeastSquaresProblem::add_row(const std::vector<double>& row, double value) {
  if (int(row.size()) != columns)
    throw Error("least squares", "a row has " + std::to_string(row.size()) + " entries; expected " +
                                     std::to_string(columns));
  a.insert(a.end(), row.begin(), row.end());
  b.push_back(value);
}

std::vector<double> solve_least_squares(const LeastSquaresProblem& problem) {
  const int m = problem.rows(), n = problem.columns;
  if (n < 1 || m < n)
    throw Error("least squares", std::to_string(m) + " equations cannot determine " +
                                     std::to_string(n) + " unknowns");
  std::vector<double> a = problem.a, b = problem.b;
  auto at = [&](int i, int j) -> double& { return a[size_t(i) * n + j]; };
  for (double v : a)
    if (!std::isfinite(v)) throw Error("least squares", "a coefficient is not finite");
  for (double v : b)
    if (!std::isfinite(v)) throw Error("least squares", "a right-hand side is not finite");

  // 1. Scale each column to unit length (x_j = y_j / scale_j): the basis's powers then weigh alike.
  std::vector<double> scale(size_t(n), 0);
  for (int j = 0; j < n; ++j) {
    double sum = 0;
    for (int i = 0; i < m; ++i) sum += at(i, j) * at(i, j);
    scale[size_t(j)] = std::sqrt(sum);
    if (!(scale[size_t(j)] > 0)) throw Error("least squares", "a column is all zeros");
    for (int i = 0; i < m; ++i) at(i, j) /= scale[size_t(j)];
  }
  // 2. Householder reflections turn A into R (upper triangular), applied to b as they go.
  for (int k = 0; k < n; ++k) {
    double norm = 0;
    for (int i = k; i < m; ++i) norm += at(i, k) * at(i, k);
    norm = std::sqrt(norm);
    if (!(norm > 1e-12))
      throw Error("least squares", "the basis functions are linearly dependent on these samples");
    // v = x − alpha·e1 with alpha of the opposite sign to x_k (no cancellation).
    const double alpha = at(k, k) > 0 ? -norm : norm;
    at(k, k) -= alpha;
    double vv = 0;
    for (int i = k; i < m; ++i) vv += at(i, k) * at(i, k);
    for (int j = k + 1; j < n; ++j) {
      double dot = 0;
      for (int i = k; i < m; ++i) dot += at(i, k) * at(i, j);
      const double f = 2 * dot / vv;
      for (int i = k; i < m; ++i) at(i, j) -= f * at(i, k);
    }
    double dot = 0;
    for (int i = k; i < m; ++i) dot += at(i, k) * b[size_t(i)];
    const double f = 2 * dot / vv;
    for (int i = k; i < m; ++i) b[size_t(i)] -= f * at(i, k);
    at(k, k) = alpha;  // R's diagonal; the rest of column k below it is no longer needed
  }
  // 3. Back substitution R y = (Qᵀb)[0..n), then undo the scaling.
  std::vector<double> x(size_t(n), 0);
  for (int k = n - 1; k >= 0; --k) {
    double sum = b[size_t(k)];
    for (int j = k + 1; j < n; ++j) sum -= at(k, j) * x[size_t(j)];
    x[size_t(k)] = sum / at(k, k);
  }
  for (int j = 0; j < n; ++j) x[size_t(j)] /= scale[size_t(j)];
  return x;
}

}  // namespace obscura
