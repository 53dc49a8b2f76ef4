// Linear least squares by QR: exact data give back the coefficients they were made with, noisy
// data the normal equations' answer (computed here in long double on a small, well-conditioned
// problem), an ill-conditioned polynomial basis still fits to rounding, and problems without a
// unique answer are errors.
#include "obscura/math/least_squares.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(LeastSquares, ExactDataGiveBackTheirCoefficients) {
  // y = 2 − 3x + 0.5x³ at 20 points of [−1, 2].
  LeastSquaresProblem p;
  p.columns = 3;
  for (int i = 0; i < 20; ++i) {
    double x = -1 + 3.0 * i / 19;
    p.add_row({1, x, x * x * x}, 2 - 3 * x + 0.5 * x * x * x);
  }
  std::vector<double> c = solve_least_squares(p);
  EXPECT_NEAR(c[0], 2, 1e-13);
  EXPECT_NEAR(c[1], -3, 1e-13);
  EXPECT_NEAR(c[2], 0.5, 1e-13);
}

TEST(LeastSquares, NoisyLineMatchesTheNormalEquations) {
  // A straight line through scattered points: the normal equations [Σ1 Σx; Σx Σx²] c = [Σy; Σxy]
  // solved by Cramer's rule in long double.
  const double xs[] = {0, 1, 2, 3, 4, 5}, ys[] = {1.1, 2.9, 5.2, 6.8, 9.1, 11.2};
  LeastSquaresProblem p;
  p.columns = 2;
  long double s1 = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
  for (int i = 0; i < 6; ++i) {
    p.add_row({1, xs[i]}, ys[i]);
    s1 += 1, sx += xs[i], sxx += xs[i] * xs[i], sy += ys[i], sxy += xs[i] * ys[i];
  }
  const long double det = s1 * sxx - sx * sx;
  std::vector<double> c = solve_least_squares(p);
  EXPECT_NEAR(c[0], double((sy * sxx - sx * sxy) / det), 1e-12);
  EXPECT_NEAR(c[1], double((s1 * sxy - sx * sy) / det), 1e-12);
}

TEST(LeastSquares, IllConditionedPowersStillFitToRounding) {
  // Powers x, x³, … x⁹ of x ∈ [1, 1.5]: nearly parallel columns (the normal equations would
  // square a condition number of ~1e8). The fitted curve follows sin x between the samples to
  // 1e-6.
  LeastSquaresProblem p;
  p.columns = 5;
  auto f = [](double x) { return std::sin(x); };
  for (int i = 0; i < 40; ++i) {
    double x = 1 + 0.5 * i / 39;
    p.add_row({x, x * x * x, std::pow(x, 5), std::pow(x, 7), std::pow(x, 9)}, f(x));
  }
  std::vector<double> c = solve_least_squares(p);
  for (int i = 0; i < 40; ++i) {
    double x = 1 + 0.5 * (i + 0.5) / 39, y = 0;
    for (int k = 0; k < 5; ++k) y += c[size_t(k)] * std::pow(x, 2 * k + 1);
    EXPECT_NEAR(y, f(x), 1e-6);
  }
}

TEST(LeastSquares, ProblemsWithoutAUniqueAnswerAreErrors) {
  LeastSquaresProblem few;
  few.columns = 3;
  few.add_row({1, 2, 3}, 1);
  EXPECT_THROW(solve_least_squares(few), Error);
  LeastSquaresProblem dependent;
  dependent.columns = 2;
  for (int i = 0; i < 5; ++i) dependent.add_row({double(i), 2.0 * i}, i);
  EXPECT_THROW(solve_least_squares(dependent), Error);
  LeastSquaresProblem wrong;
  wrong.columns = 2;
  EXPECT_THROW(wrong.add_row({1}, 1), Error);
  LeastSquaresProblem not_finite;
  not_finite.columns = 1;
  not_finite.add_row({1}, std::nan(""));
  not_finite.add_row({2}, 1);
  EXPECT_THROW(solve_least_squares(not_finite), Error);
}

}  // namespace
}  // namespace obscura
