// Gauss–Legendre quadrature nodes and weights on (0, 1), for the albedo tables the shading
// models integrate once per process (ggx_energy, charlie_sheen).
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace obscura::shading {

// The roots of P_N by Newton's iteration from the usual cosine guesses; weights for (0, 1).
template <int N>
struct GaussLegendre {
  std::array<double, N> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < N; ++i) {
      double z = std::cos(std::numbers::pi * (i + 0.75) / (N + 0.5)), dp = 1;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1, p1 = z;  // P_0, P_1, then the recurrence up to P_N
        for (int k = 2; k <= N; ++k) {
          double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1, p1 = p2;
        }
        dp = N * (z * p1 - p0) / (z * z - 1);
        double step = p1 / dp;
        z -= step;
        if (std::abs(step) < 1e-15) break;
      }
      x[i] = 0.5 * (1 - z);
      w[i] = 1 / ((1 - z * z) * dp * dp);  // the weight on (−1, 1) halved for (0, 1)
    }
  }
};

}  // namespace obscura::shading
