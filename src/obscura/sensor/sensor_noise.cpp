#include "obscura/sensor/sensor_noise.h"

#include <cmath>
#include <numbers>

#include "obscura/math/rng.h"

namespace obscura {

namespace {

// log(k!) without lgamma's global sign variable (not thread-safe): exact sums for small k,
// Stirling's series (error below 1e-10 from k = 20) beyond.
double log_factorial(double k) {
  if (k < 20) {
    double sum = 0;
    for (int i = 2; i <= int(k); ++i) sum += std::log(double(i));
    return sum;
  }
  const double x = k + 1;  // log Γ(x)
  return (x - 0.5) * std::log(x) - x + 0.5 * std::log(2 * std::numbers::pi) + 1 / (12 * x) -
         1 / (360 * x * x * x) + 1 / (1260 * x * x * x * x * x);
}

}  // namespace

double NoiseStream::uniform() {
  const uint64_t bits = hash_words(key_, pixel_, counter_++, 0x5e4507);
  return (double(bits >> 11) + 0.5) * 0x1p-53;
}

double NoiseStream::normal() {
  const double u1 = uniform(), u2 = uniform();
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
}

double NoiseStream::poisson(double mean) {
  if (!(mean > 0)) return 0;
  if (mean < 10) {
    // Inversion: walk the CDF from 0.
    double p = std::exp(-mean), cdf = p, u = uniform();
    double k = 0;
    while (u > cdf && k < 1000) {
      k += 1;
      p *= mean / k;
      cdf += p;
    }
    return k;
  }
  // PTRS (W. Hörmann, "The transformed rejection method for generating Poisson random
  // variables", Insurance: Mathematics and Economics 12, 1993), with the paper's constants.
  const double smu = std::sqrt(mean), log_mean = std::log(mean);
  const double b = 0.931 + 2.53 * smu;
  const double a = -0.059 + 0.02483 * b;
  const double inv_alpha = 1.1239 + 1.1328 / (b - 3.4);
  const double v_r = 0.9277 - 3.6224 / (b - 2);
  for (;;) {
    const double u = uniform() - 0.5, v = uniform();
    const double us = 0.5 - std::abs(u);
    const double k = std::floor((2 * a / us + b) * u + mean + 0.43);
    if (us >= 0.07 && v <= v_r) return k;
    if (k < 0 || (us < 0.013 && v > us)) continue;
    if (std::log(v) + std::log(inv_alpha) - std::log(a / (us * us) + b) <=
        -mean + k * log_mean - log_factorial(k))
      return k;
  }
}

}  // namespace obscura
