// Golden-section search: the minimum of a function that is unimodal on [a, b], found by shrinking
// the bracket by the golden ratio each step with one new evaluation (Kiefer 1953).
#pragma once

#include <cmath>

namespace obscura {

// The midpoint of the final bracket after at most `iterations` steps, stopping early once it is
// narrower than `tolerance` (0: take every step).
template <typename F>
double golden_section_minimum(F f, double a, double b, int iterations, double tolerance = 0) {
  const double golden = (std::sqrt(5.0) - 1) / 2;
  double c = b - golden * (b - a), d = a + golden * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < iterations && b - a > tolerance; ++i) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - golden * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + golden * (b - a), fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace obscura
